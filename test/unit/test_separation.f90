!> Separation (src/wa_separation.f90): profiles and mean gap against the mpmath tables of
!> tools/reference/make_separation_reference.py, the identities of doc/theory.md "Separation", the
!> no-contact MD states, and bad input.
module test_separation
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use wavyadhesion
   use wa_kinds, only: wp, pi
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   ! 16-point Gauss-Legendre on [0, 1] for the identity quadratures (the library's one
   ! literal table; test/docs/test_md_gauss_rules.py checks it against numpy)
   use wa_quadrature, only: gx => gl16_x, gw => gl16_w
   implicit none
   private

   public :: collect_separation

   !> The accuracy target (doc/accuracy-performance.md): relative 1e-12, absolute 1e-12 where |value| < 1e-3.
   real(wp), parameter :: rtol = 1.0e-12_wp, abs_below = 1.0e-3_wp


contains

   subroutine collect_separation(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("westergaard_table", test_westergaard_table), &
         new_unittest("jkr_table", test_jkr_table), &
         new_unittest("dw_table", test_dw_table), &
         new_unittest("md_table", test_md_table), &
         new_unittest("md_nocontact_table", test_nocontact_table), &
         new_unittest("traction_mean_is_load", test_traction_mean), &
         new_unittest("gap_zero_on_contact_nonnegative", test_gap_contact), &
         new_unittest("md_gap_at_c_is_h0", test_md_h0), &
         new_unittest("westergaard_work_quarter", test_westergaard_work), &
         new_unittest("gbar_touching_and_full_contact", test_gbar_limits), &
         new_unittest("dw_gbar_continuous_at_corner", test_dw_corner), &
         new_unittest("solvers_fill_gbar", test_solvers_fill), &
         new_unittest("md_nocontact_family", test_family), &
         new_unittest("md_crest_near_half", test_crest_near_half), &
         new_unittest("closed_forms_tiny_a_star", test_tiny_a_star), &
         new_unittest("bad_input", test_bad_input)]
   end subroutine collect_separation

   ! ------------------------------------------------------------------ tables

   subroutine test_westergaard_table(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/separation_westergaard.txt", model_westergaard, error)
   end subroutine test_westergaard_table

   subroutine test_jkr_table(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/separation_jkr.txt", model_jkr, error)
   end subroutine test_jkr_table

   subroutine test_dw_table(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/separation_dw.txt", model_dw, error)
   end subroutine test_dw_table

   subroutine test_md_table(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/separation_md.txt", model_md, error)
   end subroutine test_md_table

   subroutine test_nocontact_table(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_table("test/data/separation_md_nocontact.txt", model_md, error)
   end subroutine test_nocontact_table

   !> Rows: alpha mu a_star c_star gap_width p_star zone_case gbar_in x_star traction gap gbar.
   !> The state is taken from the row (the solver is tested elsewhere); prints the largest
   !> errors (relative, or absolute below 1e-3).
   subroutine compare_table(path, model, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: model
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: alpha, mu, x(1), t_ref, h_ref, g_ref, t(1), h(1), g, worst(3)
      type(params_type) :: params
      type(state_type) :: s
      integer :: unit, ios, rows, status
      character(len=512) :: line
      character(len=200) :: msg

      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      call check(error, ios == 0, "cannot open "//path)
      if (allocated(error)) return
      worst = 0.0_wp
      rows = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         read (line, *) alpha, mu, s%a_star, s%c_star, s%gap_width, s%p_star, s%zone_case, &
            s%gbar, x(1), t_ref, h_ref, g_ref
         if (model == model_westergaard) alpha = 1.0_wp
         call new_params(alpha, mu, params, status)
         call state_profile(model, params, s, x, t, h, status, msg)
         call check(error, status == wa_ok, path//": "//trim(line)//": "//trim(msg))
         if (status /= wa_ok) exit
         call state_mean_gap(model, params, s, g, status, msg)
         call check(error, status == wa_ok, path//": gbar: "//trim(msg))
         if (status /= wa_ok) exit
         ! At x* = c* (within a few ulps) the traction is ill-conditioned: DW has a
         ! square-root edge there (dp/dx ~ lambda/sqrt(c* - x*)), MD a jump from -Sigma0 to 0;
         ! the gap is continuous and is checked everywhere
         if (.not. ((model == model_dw .or. model == model_md) .and. &
               abs(abs(x(1)) - s%c_star) <= 4.0_wp*spacing(max(s%c_star, tiny(1.0_wp))))) &
            worst(1) = max(worst(1), err(t(1), t_ref))
         if (model == model_md .and. abs(abs(x(1)) - s%c_star) <= 4.0_wp*spacing(s%c_star) &
               .and. s%c_star > 0.0_wp) then
            ! MD gap at x* = c*: its slope is log-singular there (2 Sigma0 ln|c* - x*|), so a
            ! few ulps in x* (or in c* = a* + (c*-a*)) move it by ~ 2 Sigma0 (|ln d| + 10) 4 d
            worst(2) = max(worst(2), abs(h(1) - h_ref)/max(rtol*max(abs(h_ref), abs_below), &
               8.0_wp*params%sigma0*(abs(log(spacing(s%c_star))) + 10.0_wp)*spacing(s%c_star)))
         else
            worst(2) = max(worst(2), err(h(1), h_ref))
         end if
         worst(3) = max(worst(3), err(g, g_ref))
         if (maxval(worst) > 1.0_wp .and. .not. allocated(error)) then
            write (msg, '(3es24.16)') t(1), h(1), g
            call check(error, .false., path//": row "//trim(line)//" got "//trim(msg))
         end if
         rows = rows + 1
      end do
      close (unit)
      write (*, '(4x,a,i0,a,3es9.2)') "rows ", rows, "  max error traction gap gbar:", worst
      call check(error, rows > 0, path//": no rows")
      call check(error, all(worst <= 1.0_wp), path//": error above tolerance")
   end subroutine compare_table

   !> Error in units of the tolerance: relative 1e-12, absolute 1e-12 below 1e-3.
   pure real(wp) function err(got, ref)
      real(wp), intent(in) :: got, ref
      if (abs(ref) < abs_below) then
         err = abs(got - ref)/rtol
      else
         err = abs(got - ref)/(rtol*abs(ref))
      end if
      if (.not. ieee_is_finite(got)) err = huge(1.0_wp)
   end function err

   ! ------------------------------------------------------------------ identities

   !> 2 int_0^{1/2} p dx by Gauss-Legendre on [0, a] (x = a(1-u^2)), [a, c]
   !> (x = c - (c-a) u^2) and [c, 1/2], which makes every edge singularity smooth.
   function traction_mean(model, params, s) result(m)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(state_type), intent(in) :: s
      real(wp) :: m
      integer, parameter :: panels = 40
      real(wp) :: u, x, w
      integer :: k, i, piece
      m = 0.0_wp
      do piece = 1, 3
         if (piece == 2 .and. s%c_star == s%a_star) cycle
         do k = 0, panels - 1
            do i = 1, 16
               u = (k + gx(i))/panels
               select case (piece)
               case (1)
                  x = s%a_star*(1.0_wp - u*u); w = 2.0_wp*s%a_star*u
               case (2)
                  x = s%c_star - (s%c_star - s%a_star)*u*u; w = 2.0_wp*(s%c_star - s%a_star)*u
               case default
                  x = s%c_star + (0.5_wp - s%c_star)*u; w = 0.5_wp - s%c_star
               end select
               m = m + 2.0_wp*gw(i)/panels*w*state_traction(model, params, s, x)
            end do
         end do
      end do
   end function traction_mean

   !> A few states of every model at alpha = 0.3 and 1, mu = 1, 100.
   subroutine sample_states(model, params, states, n)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(state_type), intent(out) :: states(:)
      integer, intent(out) :: n
      real(wp), parameter :: a_list(5) = [1.0e-3_wp, 0.05_wp, 0.2_wp, 0.35_wp, 0.49_wp]
      type(state_type) :: found(4)
      integer :: i, k, nr, status
      n = 0
      do i = 1, size(a_list)
         call model_roots(model, params, a_list(i), found, nr, status)
         if (status /= wa_ok) cycle
         do k = 1, min(nr, size(found))
            if (n < size(states)) then
               n = n + 1
               states(n) = found(k)
            end if
         end do
      end do
   end subroutine sample_states

   subroutine test_traction_mean(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: states(24)
      integer :: model, n, k, status, ip
      real(wp), parameter :: pa(2) = [0.3_wp, 1.0_wp], pm(2) = [1.0_wp, 100.0_wp]
      character(len=120) :: what
      do ip = 1, 2
         call new_params(pa(ip), pm(ip), params, status)
         do model = model_westergaard, model_md
            call sample_states(model, params, states, n)
            do k = 1, n
               write (what, '(a,i0,a,es10.3,a,es10.3)') "traction mean, model ", model, &
                  " a* ", states(k)%a_star, " c* ", states(k)%c_star
               call check_close(error, traction_mean(model, params, states(k)), &
                  states(k)%p_star, 1.0e-11_wp, 1.0e-12_wp, trim(what))
            end do
         end do
         call md_no_contact_state(params, 0.03_wp, states(1), status)
         call check_close(error, traction_mean(model_md, params, states(1)), &
            states(1)%p_star, 1.0e-12_wp, 1.0e-13_wp, "traction mean, no contact")
      end do
   end subroutine test_traction_mean

   subroutine test_gap_contact(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: states(24)
      real(wp) :: x(201), t(201), h(201)
      integer :: model, n, k, i, status
      character(len=200) :: msg
      call new_params(0.3_wp, 1.0_wp, params, status)
      do i = 1, 201
         x(i) = -0.5_wp + (i - 1)/200.0_wp
      end do
      do model = model_westergaard, model_md
         call sample_states(model, params, states, n)
         do k = 1, n
            call state_profile(model, params, states(k), x, t, h, status, msg)
            call check(error, status == wa_ok, "profile: "//trim(msg))
            call check(error, all(h >= 0.0_wp) .and. .not. any(ieee_is_nan(h)), "gap < 0 or NaN")
            call check(error, all(pack(h, abs(x) < states(k)%a_star) == 0.0_wp), &
               "gap /= 0 on the contact")
            call check(error, .not. any(ieee_is_nan(t)), "traction NaN")
         end do
      end do
   end subroutine test_gap_contact

   subroutine test_md_h0(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: states(24)
      real(wp), parameter :: pa(3) = [0.01_wp, 0.3_wp, 3.0_wp], pm(3) = [0.1_wp, 1.0_wp, 1000.0_wp]
      integer :: ip, jm, n, k, status
      character(len=120) :: what
      do ip = 1, 3
         do jm = 1, 3
            call new_params(pa(ip), pm(jm), params, status)
            call sample_states(model_md, params, states, n)
            do k = 1, n
               if (states(k)%zone_case /= zone_inside) cycle
               write (what, '(a,2es9.2,a,es10.3)') "MD h(c) = 2 Dcod, alpha mu", pa(ip), &
                  pm(jm), " a*", states(k)%a_star
               ! x* = c* as a double is off the true c* (a* + (c*-a*)) by up to an
               ! ulp d, and the gap slope is log-singular at c*: allow
               ! |h'| d ~ (2 Sigma0 (|ln d| + 10) + 3 h0/(c*-a*)) d
               call check_close(error, state_gap(model_md, params, states(k), &
                  states(k)%c_star), 2.0_wp*params%dcod, 1.0e-12_wp, (2.0_wp*params%sigma0* &
                  (abs(log(spacing(states(k)%c_star))) + 10.0_wp) + 3.0_wp*params%dcod/ &
                  states(k)%gap_width)*spacing(states(k)%c_star), trim(what))
            end do
            call md_no_contact_state(params, 1.0e-3_wp, states(1), status)
            if (status == wa_ok) call check_close(error, state_gap(model_md, params, &
               states(1), states(1)%c_star), 2.0_wp*params%dcod, 1.0e-12_wp, 1.0e-15_wp, &
               "no contact h(c) = 2 Dcod")
         end do
      end do
   end subroutine test_md_h0

   !> int P dgbar from full contact to touching = 1/4, as int_0^1 gbar dP
   !> = int_0^{1/2} gbar(a) pi sin(2 pi a) da (panels graded towards a = 0).
   subroutine test_westergaard_work(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: total, lo, hi, a
      integer :: k, i
      total = 0.0_wp
      hi = 0.5_wp
      do k = 1, 60
         lo = hi/2.0_wp
         if (k == 60) lo = 0.0_wp
         do i = 1, 16
            a = lo + (hi - lo)*gx(i)
            total = total + (hi - lo)*gw(i)*westergaard_mean_gap(a)*pi*sin(2.0_wp*pi*a)
         end do
         hi = lo
      end do
      call check_close(error, total, 0.25_wp, 1.0e-13_wp, what="Westergaard int P dgbar")
   end subroutine test_westergaard_work

   subroutine test_gbar_limits(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: s
      integer :: status
      call check_close(error, westergaard_mean_gap(0.0_wp), 1.0_wp, 0.0_wp, what="W a*=0")
      call check_close(error, westergaard_mean_gap(1.0e-9_wp), 1.0_wp, 1.0e-15_wp, &
         what="W a*->0")
      call check_close(error, jkr_mean_gap(0.3_wp, 0.0_wp), 1.0_wp, 0.0_wp, what="JKR a*=0")
      call check_close(error, jkr_mean_gap(0.3_wp, 1.0e-14_wp), 1.0_wp, 3.0e-5_wp, &
         what="JKR a*->0")
      call check_close(error, jkr_mean_gap(0.3_wp, 1.0e-20_wp), 1.0_wp, 1.0e-8_wp, &
         what="JKR a*->0")
      call check_close(error, westergaard_mean_gap(0.5_wp), 0.0_wp, 0.0_wp, what="W full")
      call check_close(error, jkr_mean_gap(0.3_wp, 0.5_wp), 0.0_wp, 0.0_wp, what="JKR full")
      call new_params(0.3_wp, 1.0_wp, params, status)
      call dw_equilibrium(params, 0.5_wp, s, status)
      call check_close(error, s%gbar, 0.0_wp, 0.0_wp, what="DW full contact")
      call md_equilibrium(params, 0.5_wp, s, status)
      call check_close(error, s%gbar, 0.0_wp, 0.0_wp, what="MD full contact")
      ! MD case 2 (uniform -Sigma0 adds no deformation): gbar = Westergaard's
      call new_params(0.3_wp, 0.01_wp, params, status)
      call md_equilibrium(params, 0.2_wp, s, status)
      call check(error, s%zone_case == zone_whole_period, "MD mu=0.01 a*=0.2 should be case 2")
      call check_close(error, s%gbar, westergaard_mean_gap(0.2_wp), 1.0e-15_wp, &
         what="MD case 2")
   end subroutine test_gbar_limits

   !> The a* where DW switches from case 1 to case 2 (alpha = 0.6, mu = 1 and
   !> alpha = 0.3, mu = 5), by bisection on the zone case; gbar on both sides agrees.
   subroutine test_dw_corner(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: pa(2) = [0.6_wp, 0.3_wp], pm(2) = [1.0_wp, 5.0_wp]
      type(params_type) :: params
      type(state_type) :: s_lo, s_hi, s
      real(wp) :: lo, hi, mid
      integer :: ip, i, status, zone_lo
      do ip = 1, 2
         call new_params(pa(ip), pm(ip), params, status)
         lo = 1.0e-3_wp
         hi = 0.499_wp
         call dw_equilibrium(params, lo, s_lo, status)
         call dw_equilibrium(params, hi, s_hi, status)
         zone_lo = s_lo%zone_case
         call check(error, s_lo%zone_case /= s_hi%zone_case, "DW corner not bracketed")
         if (allocated(error)) return
         do i = 1, 60
            mid = 0.5_wp*(lo + hi)
            call dw_equilibrium(params, mid, s, status)
            if (s%zone_case == zone_lo) then
               lo = mid; s_lo = s
            else
               hi = mid; s_hi = s
            end if
         end do
         call check_close(error, s_lo%gbar, s_hi%gbar, 1.0e-11_wp, what="DW gbar at the corner")
      end do
   end subroutine test_dw_corner

   subroutine test_solvers_fill(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: states(4), s
      integer :: model, n, k, status
      real(wp) :: g
      call new_params(0.3_wp, 1.0_wp, params, status)
      do model = model_dw, model_md
         call model_roots(model, params, 0.2_wp, states, n, status)
         call check(error, status == wa_ok .and. n >= 1, "roots")
         do k = 1, min(n, 4)
            call state_mean_gap(model, params, states(k), g, status)
            call check_close(error, states(k)%gbar, g, 1.0e-14_wp, what="roots fill gbar")
         end do
         call model_equilibrium(model, params, 0.2_wp, s, status)
         call check_close(error, s%gbar, states(1)%gbar, 1.0e-14_wp, what="equilibrium gbar")
      end do
   end subroutine test_solvers_fill

   !> The no-contact family: starts at the first interaction (gbar = 1 + 2 Dcod, P* = 0),
   !> ends with crest gap 0 at a closure; Dugdale consistency h <= h0 inside the zone,
   !> h >= h0 outside; closure at alpha = 0.3, mu = 1 near c* = 0.10 (doc/theory.md, "Separation").
   subroutine test_family(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: pa(3) = [0.3_wp, 0.3_wp, 3.0_wp], pm(3) = [1.0_wp, 0.01_wp, 10.0_wp]
      type(params_type) :: params
      type(state_type) :: states(40)
      real(wp) :: c_close(2), x(101), t(101), h(101), h0
      integer :: ip, n, k, i, status, n_close
      logical :: stretch
      character(len=200) :: msg
      do i = 1, 101
         x(i) = (i - 1)/200.0_wp
      end do
      do ip = 1, 3
         call new_params(pa(ip), pm(ip), params, status)
         h0 = 2.0_wp*params%dcod
         call md_no_contact_family(params, 1, states, n, status, msg)
         call check(error, status == wa_ok .and. n == size(states), "family: "//trim(msg))
         if (allocated(error)) return
         call check_close(error, states(1)%gbar, 1.0_wp + h0, 1.0e-15_wp, what="first gbar")
         call check_close(error, states(1)%p_star, 0.0_wp, 0.0_wp, what="first P*")
         call check_close(error, state_gap(model_md, params, states(n), 0.0_wp), 0.0_wp, &
            0.0_wp, 1.0e-12_wp, what="last crest gap")
         do k = 1, n
            call state_profile(model_md, params, states(k), x, t, h, status, msg)
            call check(error, status == wa_ok, "family profile: "//trim(msg))
            call check(error, all(pack(h, x < states(k)%c_star) <= h0*(1.0_wp + 1.0e-12_wp)), &
               "family: gap above h0 inside the zone")
            call check(error, all(pack(h, x > states(k)%c_star) >= h0*(1.0_wp - 1.0e-12_wp)), &
               "family: gap below h0 outside the zone")
            call check(error, all(h >= 0.0_wp), "family: negative gap")
         end do
      end do
      call new_params(0.3_wp, 1.0_wp, params, status)
      call md_no_contact_closures(params, c_close, n_close, stretch, status)
      call check(error, n_close >= 1 .and. abs(c_close(1) - 0.10_wp) < 0.01_wp, &
         "closure at alpha 0.3 mu 1 near c* = 0.10")
      call check_close(error, md_no_contact_crest_gap(params, c_close(1)), 0.0_wp, 0.0_wp, &
         1.0e-13_wp, what="crest gap at the closure")
   end subroutine test_family

   !> Crest gap and mean gap of the no-contact MD states at large Sigma0 against
   !> tools/reference/make_crest_reference.py (mpmath, 60 digits; the Clausen forms checked there against
   !> the quadrature of the gap slope). Near c* = 1/2 the two-term Clausen form rounded 4 pi c*
   !> next to 2 pi: H(1/2) came out as -2.5e7 instead of 2 Dcod - 2 = 4.95 at the reproducer of
   !> the wrong-status defect, so the reopening closure and the piece-2 states went wrong.
   subroutine test_crest_near_half(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: c_repro(6) = [0.5_wp, 0.5_wp - 2.0_wp**(-52), &
         0.5_wp - 2.0_wp**(-40), 0.5_wp - 2.0_wp**(-20), 0.4_wp, 0.3_wp]
      real(wp), parameter :: h_repro(6) = [4.9539749173282613126_wp, -266225860.7280932372_wp, &
         -832827263769.28747319_wp, -423034838415301097.94_wp, -5.0069483319398392594e+21_wp, &
         -5.4058733102602628048e+21_wp]
      real(wp), parameter :: c_near(3) = [0.5_wp - 2.0_wp**(-45), 0.5_wp - 2.0_wp**(-36), &
         1.0e-12_wp]
      real(wp), parameter :: h_near(3) = [71.67989429267234775_wp, 71.381374880105640664_wp, &
         73.680038885003214903_wp]
      real(wp), parameter :: g_near(3) = [72.679911092398175594_wp, 72.389976339729496617_wp, &
         74.702886991634118358_wp]
      type(params_type) :: params
      type(state_type) :: s
      real(wp) :: c_close(2), g
      integer :: i, n_close, status
      logical :: stretch
      character(len=200) :: msg

      call new_params(194144313374.73993_wp, 256617602357780.94_wp, params, status)
      do i = 1, size(c_repro)
         call check_close(error, md_no_contact_crest_gap(params, c_repro(i)), h_repro(i), &
            1.0e-12_wp, what="crest gap, Sigma0 = 8.5e21")
      end do
      ! closures: 2.9458563258900852743e-22, and 1/2 - 2.7e-24 (1/2 in double precision)
      msg = ""
      call md_no_contact_closures(params, c_close, n_close, stretch, status, msg)
      call check(error, status == wa_ok .and. n_close == 2 .and. stretch, "closures: "//trim(msg))
      call check_close(error, c_close(1), 2.9458563258900852743e-22_wp, 1.0e-10_wp, &
         what="first closure")
      call check_close(error, c_close(2), 0.5_wp, 0.0_wp, what="reopening (within 3e-24 of 1/2)")
      call new_params(1.0e5_wp, 1.0e5_wp, params, status)
      do i = 1, size(c_near)
         call check_close(error, md_no_contact_crest_gap(params, c_near(i)), h_near(i), &
            1.0e-12_wp, what="crest gap, Sigma0 = 2.1e8")
         msg = ""
         call md_no_contact_state(params, c_near(i), s, status, msg)
         call check(error, status == wa_ok, "no-contact state: "//trim(msg))
         call check_close(error, s%gbar, g_near(i), 1.0e-12_wp, what="gbar, Sigma0 = 2.1e8")
         call state_mean_gap(model_md, params, s, g, status)
         call check_close(error, g, g_near(i), 1.0e-12_wp, what="state_mean_gap")
      end do
   end subroutine test_crest_near_half

   !> Westergaard and JKR at extreme a* (issue 7: wa_profile(1, 5.53e-07, 1.3, 5.59e-266,
   !> 5.59e-266) returned wa_numerical_error; the Westergaard traction at a* = 1e-300 was 0
   !> with wa_ok; subnormal a* gave NaN or a JKR load 2 % off) against
   !> test/data/separation_tiny.txt (tools/reference/make_tiny_contact_reference.py, mpmath): the
   !> profile through model_profile, P*, gbar and the kernels' elemental forms, relative 1e-13
   !> or absolute 1e-320 (results in the subnormal range are rounded to its grid).
   subroutine test_tiny_a_star(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: path = "test/data/separation_tiny.txt"
      real(wp), parameter :: rtol = 1.0e-13_wp, atol = 1.0e-320_wp
      real(wp) :: alpha, a, x(2), t(2), h(2), t_ref, h_ref, p_ref, g_ref
      type(params_type) :: params
      type(state_type) :: s
      integer :: unit, ios, model, status, rows
      character(len=512) :: line
      character(len=200) :: msg

      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      call check(error, ios == 0, "cannot open "//path)
      if (allocated(error)) return
      rows = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         read (line, *) model, alpha, a, x(1), t_ref, h_ref, p_ref, g_ref
         rows = rows + 1
         call new_params(max(alpha, 1.0e-12_wp), 1.3_wp, params, status)
         x(2) = a                                        ! the contact edge
         msg = ""
         call model_profile(model, params, a, x, t, h, s, status, msg, a)
         call check(error, status == wa_ok, "tiny a*: "//trim(line)//": "//trim(msg))
         if (allocated(error)) exit
         call check_close(error, t(1), t_ref, rtol, atol, what="traction: "//trim(line))
         call check_close(error, h(1), h_ref, rtol, atol, what="gap: "//trim(line))
         call check_close(error, s%p_star, p_ref, rtol, atol, what="P*: "//trim(line))
         call check_close(error, s%gbar, g_ref, rtol, atol, what="gbar: "//trim(line))
         call check_close(error, h(2), 0.0_wp, 0.0_wp, 0.0_wp, what="gap at the edge")
         if (model == model_jkr) then
            call check(error, t(2) < -huge(1.0_wp), "JKR traction at the edge: -Infinity")
            call check_close(error, jkr_load(alpha, a), p_ref, rtol, atol, what="jkr_load")
            call check_close(error, jkr_mean_gap(alpha, a), g_ref, rtol, atol, what="jkr_mean_gap")
         else
            call check_close(error, t(2), 0.0_wp, 0.0_wp, 0.0_wp, what="traction at the edge")
            call check_close(error, westergaard_load(a), p_ref, rtol, atol, what="westergaard_load")
            call check_close(error, westergaard_mean_gap(a), g_ref, rtol, atol, &
               what="westergaard_mean_gap")
            call check_close(error, westergaard_pressure(a, x(1)), t_ref, rtol, atol, &
               what="westergaard_pressure: "//trim(line))
            call check_close(error, westergaard_gap(a, x(1)), h_ref, rtol, atol, &
               what="westergaard_gap: "//trim(line))
            call check_close(error, westergaard_displacement(a, x(1)), &
               h_ref - 2.0_wp*sin(pi*x(1))**2, rtol, 1.0e-15_wp, what="westergaard_displacement")
         end if
         if (allocated(error)) exit
      end do
      close (unit)
      call check(error, rows == 88, "separation_tiny.txt: expected 88 rows")
      ! the ends: a* = 0 (touching, both models): traction 0, gap 2 sin^2(pi x*);
      ! Westergaard a* = 1/2 (full contact at P* = 1): traction 1 + cos(2 pi x*), gap 0
      x = [0.0_wp, 0.3_wp]
      call new_params(5.53e-7_wp, 1.3_wp, params, status)
      do model = model_westergaard, model_jkr
         call model_profile(model, params, 0.0_wp, x, t, h, s, status)
         call check(error, status == wa_ok .and. all(t == 0.0_wp), "a* = 0: traction 0")
         call check_close(error, h(2), 2.0_wp*sin(0.3_wp*pi)**2, 1.0e-15_wp, what="a* = 0 gap")
         call check_close(error, s%gbar, 1.0_wp, 0.0_wp, what="a* = 0 gbar")
      end do
      call model_profile(model_westergaard, params, 0.5_wp, x, t, h, s, status)
      call check(error, status == wa_ok .and. all(h == 0.0_wp), "a* = 1/2: gap 0")
      call check_close(error, t(2), 1.0_wp + cos(0.6_wp*pi), 1.0e-15_wp, what="a* = 1/2 traction")
   end subroutine test_tiny_a_star

   subroutine test_bad_input(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: s, states(4)
      real(wp) :: x(2), t(2), h(2), t1(1), g, cl(2)
      integer :: status, n
      logical :: stretch
      character(len=200) :: msg
      call new_params(0.3_wp, 1.0_wp, params, status)
      call dw_equilibrium(params, 0.2_wp, s, status)
      x = [0.1_wp, 0.3_wp]
      msg = ""
      call state_profile(7, params, s, x, t, h, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "bad model")
      msg = ""
      call state_profile(model_dw, params, s, x, t1, h, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "bad size")
      x(2) = ieee_nan()
      msg = ""
      call state_profile(model_dw, params, s, x, t, h, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "NaN x")
      s%c_star = 0.1_wp
      msg = ""
      call state_mean_gap(model_dw, params, s, g, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "c < a")
      call check(error, .not. ieee_is_nan(g), "gbar NaN on error")
      call check(error, ieee_is_nan(state_gap(model_dw, params, s, 0.3_wp)), &
         "elemental gap: NaN for an invalid state")
      s%c_star = 0.3_wp; s%zone_case = zone_no_contact
      msg = ""
      call state_mean_gap(model_dw, params, s, g, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "zone 0 for DW")
      msg = ""
      call md_no_contact_state(params, 0.7_wp, s, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "c* = 0.7")
      msg = ""
      call md_no_contact_state(params, 0.5_wp, s, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, &
         "c* = 1/2 without crest gap")
      msg = ""
      call md_no_contact_state(params, 0.3_wp, s, status, msg)
      call check(error, status == wa_no_solution .and. len_trim(msg) > 0, &
         "c* beyond the closure")
      msg = ""
      call md_no_contact_family(params, 3, states, n, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "piece 3")
      msg = ""
      call md_no_contact_family(params, 1, states(1:2), n, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "2 states")
      params%alpha = -1.0_wp
      msg = ""
      call md_no_contact_closures(params, cl, n, stretch, status, msg)
      call check(error, status == wa_invalid_argument .and. len_trim(msg) > 0, "bad params")
   end subroutine test_bad_input

   real(wp) function ieee_nan()
      use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
      ieee_nan = ieee_value(1.0_wp, ieee_quiet_nan)
   end function ieee_nan

end module test_separation
