!> Tests of the Maugis-Dugdale module wa_md: Psi_c and the roots against mpmath
!> (tools/reference/md_reference.py and test/data/md.txt), the JKR and Westergaard limits, the
!> special and invalid arguments, and a NaN-free sweep over the extended range.
module test_md
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact
   use wa_md, only: md_equilibrium, md_roots, md_load, md_opening, md_psi_c, &
      md_midgap_opening, md_options, md_prepare_options, md_psi_gauss, md_psi_qaws, &
      md_psi_qag, md_psi_qags
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_md

   !> Psi_c is summed by fixed Gauss rules: measured error <= 3.2e-15 (quadrature study).
   real(wp), parameter :: psi_tol = 1.0e-13_wp
   !> the accuracy target (doc/accuracy-performance.md) for solved quantities.
   real(wp), parameter :: root_tol = 1.0e-12_wp

contains

   !> The md suite.
   subroutine collect_md(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("psi_c_mpmath", test_psi_c_mpmath), &
         new_unittest("psi_c_full_gap", test_psi_c_full_gap), &
         new_unittest("load_and_opening_formulas", test_formulas), &
         new_unittest("roots_mpmath", test_roots_mpmath), &
         new_unittest("two_roots_and_case2", test_two_roots), &
         new_unittest("extended_range_mpmath", test_extended_mpmath), &
         new_unittest("principal_state", test_principal), &
         new_unittest("large_mu_jkr", test_large_mu), &
         new_unittest("small_mu_westergaard", test_small_mu), &
         new_unittest("full_contact_and_no_contact", test_special), &
         new_unittest("invalid_arguments", test_invalid), &
         new_unittest("capacity_too_small", test_capacity), &
         new_unittest("no_nan_extended_grid", test_grid), &
         new_unittest("reference_table", test_table), &
         new_unittest("options", test_options)]
   end subroutine collect_md

   !> Psi_c (2.27d) against mpmath (tools/reference/md_reference.py psi, 32 digits), including
   !> a* -> 0, a* -> 1/2, a zone of 1e-12 relative width and c* -> 1/2.
   subroutine test_psi_c_mpmath(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: cases(3, 8) = reshape([ &
         1e-12_wp, 0.1499999999997_wp, -7.720344549311831923359877_wp, &
         1e-06_wp, 0.3499993_wp, -8.952484786906815291068523_wp, &
         0.05_wp, 0.4455_wp, -2.478074969412642821551489_wp, &
         0.25_wp, 2.5e-07_wp, -0.0000005000002617993329454586556_wp, &
         0.25_wp, 0.2475_wp, -0.8520965345849996827049214_wp, &
         0.45_wp, 0.03499999999999999_wp, -0.0850463547634249738374887_wp, &
         0.499999_wp, 9.999999999732444e-13_wp, -2.000000333280022219937622e-12_wp, &
         0.499999999999_wp, 9.999778782798786e-15_wp, -2.003309145159420890226027e-14_wp], &
         [3, 8])
      integer :: i
      character(len=40) :: what
      do i = 1, size(cases, 2)
         write (what, '("Psi_c case ",i0)') i
         call check_close(error, md_psi_c(cases(1, i), cases(2, i)), cases(3, i), psi_tol, &
            what=trim(what))
      end do
   end subroutine test_psi_c_mpmath

   !> At c* = 1/2 the Dugdale part of the opening vanishes: Psi_c = -artanh(cos(pi a*)).
   !> (Here K is summed over ~200 levels, T = e^300.)
   subroutine test_psi_c_full_gap(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: as(4) = [1e-9_wp, 0.01_wp, 0.3_wp, 0.49_wp]
      real(wp) :: q, one_minus_q
      integer :: i
      do i = 1, size(as)
         q = cos(pi*as(i))
         one_minus_q = 2.0_wp*sin(0.5_wp*pi*as(i))**2
         call check_close(error, md_psi_c(as(i), 0.5_wp - as(i)), &
            -0.5_wp*log((1.0_wp + q)/one_minus_q), psi_tol, what="Psi_c at c* = 1/2")
      end do
   end subroutine test_psi_c_full_gap

   !> md_load and md_opening against (2.27a), (2.27b) written in c* directly, where that
   !> direct form is well conditioned (moderate a*, c*).
   subroutine test_formulas(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      real(wp) :: a, gap, c, aa, cc, chi1, chi2, p, delta
      integer :: status
      call new_params(0.6_wp, 2.0_wp, params, status)
      a = 0.15_wp
      gap = 0.2_wp
      c = a + gap
      aa = sin(pi*a)
      cc = sin(pi*c)
      p = aa**2 - params%sigma0*(1.0_wp - (2.0_wp/pi)*asin(cos(pi*c)/cos(pi*a)))   ! (2.27a)
      chi1 = sqrt(cc**2 - aa**2)
      chi2 = log((cc + chi1)/aa)
      delta = chi1*cc - p*chi2 + params%sigma0*md_psi_c(a, gap)                     ! (2.27b)
      call check_close(error, md_load(params, a, gap), p, 1.0e-14_wp, what="(2.27a)")
      call check_close(error, md_opening(params, a, gap), delta, 1.0e-13_wp, what="(2.27b)")
      call check_close(error, md_opening(params, a, 0.5_wp - a), md_midgap_opening(a), &
         1.0e-13_wp, what="opening at c* = 1/2")
      call check_close(error, md_midgap_opening(a), &
         cos(pi*a) - aa**2*log((1.0_wp + cos(pi*a))/aa), 1.0e-14_wp, what="midgap opening")
   end subroutine test_formulas

   !> Single-root points against mpmath (test/data/md.txt rows; the first also from
   !> tools/reference/md_reference.py roots 0.3 1 0.2).
   subroutine test_roots_mpmath(error)
      type(error_type), allocatable, intent(out) :: error
      call check_state(error, 0.3_wp, 1.0_wp, 0.2_wp, 1, zone_inside, &
         0.072814573528505961811_wp, 0.16819645465202030638_wp)
      call check_state(error, 0.6_wp, 3.0_wp, 0.3_wp, 1, zone_inside, &
         0.029366976378105584125_wp, -0.041542533868012654912_wp)
      call check_state(error, 1.0_wp, 1000.0_wp, 0.25_wp, 1, zone_inside, &
         4.010449891365390849e-7_wp, -0.50000000000045858286_wp)
      call check_state(error, 0.01_wp, 0.001_wp, 0.1_wp, 1, zone_whole_period, &
         0.39999999999999999445_wp, 0.095445572449299619281_wp)
   end subroutine test_roots_mpmath

   !> alpha = 0.1, mu = 5, a* = 0.45: two case-1 roots and the case-2 state.
   subroutine test_two_roots(error)
      type(error_type), allocatable, intent(out) :: error
      call check_state(error, 0.1_wp, 5.0_wp, 0.45_wp, 1, zone_inside, &
         0.0035232066624688497229_wp, 0.72021717353780981669_wp, n_expected=3)
      call check_state(error, 0.1_wp, 5.0_wp, 0.45_wp, 2, zone_inside, &
         0.049513637477775675366_wp, -0.083792765744520708239_wp, n_expected=3)
      call check_state(error, 0.1_wp, 5.0_wp, 0.45_wp, 3, zone_whole_period, &
         0.049999999999999988898_wp, -0.090421047236082557478_wp, n_expected=3)
   end subroutine test_two_roots

   !> Extended range (test/data/md_extended.txt rows): mu = 1e6 with a* -> 1/2, where the
   !> second root has 1/2 - c* = 5e-17; mu = 1e4 with a* = 1e-12; mu = 1e6, a* = 1/4.
   subroutine test_extended_mpmath(error)
      type(error_type), allocatable, intent(out) :: error
      call check_state(error, 1e-4_wp, 1e6_wp, 0.499999999_wp, 1, zone_inside, &
         8.6402633586445295825e-16_wp, -0.78412460570629307551_wp, n_expected=3)
      call check_state(error, 1e-4_wp, 1e6_wp, 0.499999999_wp, 2, zone_inside, &
         9.9999997574384205019e-10_wp, -2130.8985408909124636_wp, n_expected=3)
      call check_state(error, 0.3_wp, 1e4_wp, 1e-12_wp, 1, zone_inside, &
         2.5918810269409190462e-9_wp, -2.2996404347421989138e-5_wp)
      call check_state(error, 1.0_wp, 1e6_wp, 0.25_wp, 1, zone_inside, &
         4.0104532599226226794e-13_wp, -0.5_wp)
   end subroutine test_extended_mpmath

   !> md_equilibrium returns the first state of md_roots.
   subroutine test_principal(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: state, states(4)
      integer :: status, n
      call new_params(0.1_wp, 5.0_wp, params, status)
      call md_equilibrium(params, 0.45_wp, state, status)
      call check(error, status == wa_ok, "md_equilibrium status")
      call md_roots(params, 0.45_wp, states, n, status)
      call check(error, status == wa_ok .and. n == 3, "md_roots: three states")
      if (allocated(error)) return
      call check(error, state%c_star == states(1)%c_star .and. &
         state%p_star == states(1)%p_star .and. state%zone_case == zone_inside, &
         "principal state is the smallest-c* case-1 root")
   end subroutine test_principal

   !> mu -> inf: P* -> sin^2(pi a*) - alpha sqrt(tan(pi a*)) (JKR, (3.4)); the difference
   !> falls as mu^-2 (measured 1.1e-5 (100/mu)^2 .. 2.7e-5 (100/mu)^2 at alpha = 0.3).
   subroutine test_large_mu(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: mus(2) = [1e3_wp, 1e6_wp], as(3) = [0.1_wp, 0.25_wp, 0.4_wp]
      type(params_type) :: params
      type(state_type) :: state
      real(wp) :: p_jkr
      integer :: i, j, status
      do i = 1, size(mus)
         call new_params(0.3_wp, mus(i), params, status)
         do j = 1, size(as)
            call md_equilibrium(params, as(j), state, status)
            call check(error, status == wa_ok .and. state%zone_case == zone_inside, &
               "large mu: case-1 state")
            p_jkr = sin(pi*as(j))**2 - 0.3_wp*sqrt(tan(pi*as(j)))
            call check_close(error, state%p_star, p_jkr, 0.0_wp, &
               atol=4.0e-5_wp*(100.0_wp/mus(i))**2, what="JKR limit")
            call check(error, state%gap_width < 1e-6_wp*(1e3_wp/mus(i))**2, &
               "large mu: the zone shrinks as mu^-2")
         end do
      end do
   end subroutine test_large_mu

   !> mu -> 0: Westergaard, P* -> sin^2(pi a*) (3.1), case 2 with P* = A^2 - Sigma0;
   !> mu = 0 exactly gives P* = A^2.
   subroutine test_small_mu(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: state
      integer :: status
      call new_params(0.3_wp, 1e-4_wp, params, status)
      call md_equilibrium(params, 0.2_wp, state, status)
      call check(error, status == wa_ok .and. state%zone_case == zone_whole_period, &
         "small mu: case 2")
      call check_close(error, state%p_star, sin(pi*0.2_wp)**2 - params%sigma0, 1e-14_wp, &
         what="small mu: P* = A^2 - Sigma0")
      call check(error, abs(state%p_star - sin(pi*0.2_wp)**2) < 1e-4_wp, "small mu: Westergaard")
      call new_params(0.3_wp, 0.0_wp, params, status)
      call md_equilibrium(params, 0.2_wp, state, status)
      call check(error, status == wa_ok .and. state%zone_case == zone_whole_period .and. &
         state%c_star == 0.5_wp, "mu = 0: case 2")
      call check_close(error, state%p_star, sin(pi*0.2_wp)**2, 1e-15_wp, what="mu = 0: P* = A^2")
   end subroutine test_small_mu

   !> a* = 1/2: full contact at its threshold P* = 1 - Sigma0 (zone_case 3);
   !> a* = 0: no contact, wa_no_solution with a message.
   subroutine test_special(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: state, states(3)
      integer :: status, n
      character(len=200) :: msg
      call new_params(0.6_wp, 2.0_wp, params, status)
      call md_equilibrium(params, 0.5_wp, state, status)
      call check(error, status == wa_ok .and. state%zone_case == zone_full_contact .and. &
         state%c_star == 0.5_wp .and. state%gap_width == 0.0_wp, "a* = 1/2: full contact")
      call check_close(error, state%p_star, 1.0_wp - params%sigma0, 1e-15_wp, &
         what="a* = 1/2: P* = 1 - Sigma0")
      call md_roots(params, 0.5_wp, states, n, status)
      call check(error, status == wa_ok .and. n == 1, "a* = 1/2: one state")
      msg = ""
      call md_equilibrium(params, 0.0_wp, state, status, msg)
      call check(error, status == wa_no_solution .and. len_trim(msg) > 0, &
         "a* = 0: wa_no_solution with a message")
   end subroutine test_special

   !> NaN, a* < 0, a* > 1/2 -> wa_invalid_argument, message naming a_star.
   subroutine test_invalid(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: state, states(2)
      real(wp) :: bad(3)
      integer :: status, n, i
      character(len=200) :: msg
      call new_params(0.3_wp, 1.0_wp, params, status)
      bad = [ieee_value(1.0_wp, ieee_quiet_nan), -0.1_wp, 0.6_wp]
      do i = 1, size(bad)
         msg = ""
         call md_equilibrium(params, bad(i), state, status, msg)
         call check(error, status == wa_invalid_argument .and. index(msg, "a_star") > 0, &
            "md_equilibrium: invalid a_star -> wa_invalid_argument, message")
         msg = ""
         call md_roots(params, bad(i), states, n, status, msg)
         call check(error, status == wa_invalid_argument .and. index(msg, "a_star") > 0 &
            .and. n == 0, "md_roots: invalid a_star -> wa_invalid_argument, message")
      end do
      call check(error, md_psi_c(0.2_wp, 0.4_wp) /= md_psi_c(0.2_wp, 0.4_wp), &
         "md_psi_c: NaN outside its domain")
   end subroutine test_invalid

   !> Three states, room for one: the first is stored, n_roots = 3.
   subroutine test_capacity(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: states(1)
      integer :: status, n
      character(len=200) :: msg
      call new_params(0.1_wp, 5.0_wp, params, status)
      msg = ""
      call md_roots(params, 0.45_wp, states, n, status, msg)
      call check(error, status == wa_capacity_too_small .and. n == 3 .and. &
         len_trim(msg) > 0, "capacity 1 of 3: wa_capacity_too_small, n_roots = 3")
      call check_close(error, states(1)%gap_width, 0.0035232066624688497229_wp, root_tol, &
         what="capacity: first state stored")
   end subroutine test_capacity

   !> alpha in [1e-4, 10], mu in [1e-4, 1e6], a* in {1e-12, 1e-6, 1/4, 1/2-1e-6,
   !> 1/2-1e-12}: every point gives finite, ordered states that solve (2.27b), or
   !> wa_no_solution with a message; never NaN.
   subroutine test_grid(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: alphas(6) = [1e-4_wp, 1e-3_wp, 1e-2_wp, 0.1_wp, 1.0_wp, 10.0_wp]
      real(wp), parameter :: mus(6) = [1e-4_wp, 1e-2_wp, 1.0_wp, 1e2_wp, 1e4_wp, 1e6_wp]
      real(wp), parameter :: as(5) = [1e-12_wp, 1e-6_wp, 0.25_wp, 0.5_wp - 1e-6_wp, &
         0.5_wp - 1e-12_wp]
      type(params_type) :: params
      type(state_type) :: states(8)
      integer :: i, j, k, status, n
      character(len=200) :: msg
      do i = 1, size(alphas)
         do j = 1, size(mus)
            call new_params(alphas(i), mus(j), params, status)
            do k = 1, size(as)
               msg = ""
               call md_roots(params, as(k), states, n, status, msg)
               if (status == wa_no_solution) then
                  call check(error, len_trim(msg) > 0, "grid: no_solution without message")
               else
                  call check(error, status == wa_ok .and. n >= 1, "grid: unexpected status")
                  if (status == wa_ok) call check_states(error, params, as(k), states(1:n))
               end if
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_grid

   !> Every row of test/data/md.txt (mpmath, tools/reference/make_reference.py) where that file is
   !> present: same states, c*, c*-a* and P* to 1e-12 (P* absolute below 1e-3).
   subroutine test_table(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: path = "test/data/md.txt"
      real(wp) :: row(6), worst(3)
      integer :: unit, ios, zone, n_rows, n_bad
      character(len=512) :: line
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      if (ios /= 0) return                     ! table not generated: nothing to compare
      worst = 0.0_wp
      n_rows = 0
      n_bad = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#" .or. len_trim(line) == 0) cycle
         read (line, *) row, zone
         n_rows = n_rows + 1
         call compare_row(row, zone, worst, n_bad)
      end do
      close (unit)
      print '(4x,a,i0,a,3es9.2,a,i0)', path//": ", n_rows, " states; max rel err c*, c*-a*, P* ", &
         worst, "; rows not matched ", n_bad
      call check(error, n_rows > 0 .and. n_bad == 0, path//": states differ")
      call check(error, all(worst <= root_tol), path//": error above 1e-12")
   end subroutine test_table

   ! ------------------------------------------------------------ helpers

   !> The k-th of n_expected states at (alpha, mu, a*): zone case, c*-a*, c*, P*.
   subroutine check_state(error, alpha, mu, a_star, k, zone, gap, p, n_expected)
      type(error_type), allocatable, intent(inout) :: error
      real(wp), intent(in) :: alpha, mu, a_star, gap, p
      integer, intent(in) :: k, zone
      integer, intent(in), optional :: n_expected
      type(params_type) :: params
      type(state_type) :: states(8)
      integer :: status, n, n_want
      character(len=80) :: what
      n_want = 1
      if (present(n_expected)) n_want = n_expected
      write (what, '("alpha ",es8.1," mu ",es8.1," a* ",es14.7," state ",i0,":")') &
         alpha, mu, a_star, k
      call new_params(alpha, mu, params, status)
      call md_roots(params, a_star, states, n, status)
      call check(error, status == wa_ok .and. n == n_want, trim(what)//" number of states")
      if (allocated(error)) return
      call check(error, states(k)%zone_case == zone, trim(what)//" zone case")
      call check_close(error, states(k)%gap_width, gap, root_tol, what=trim(what)//" c*-a*")
      call check_close(error, states(k)%c_star, a_star + gap, root_tol, what=trim(what)//" c*")
      call check_close(error, states(k)%p_star, p, root_tol, atol=1e-15_wp, &
         what=trim(what)//" P*")
   end subroutine check_state

   !> States of one point: finite, a* < c* <= 1/2, case-1 ones increasing, with P* from
   !> (2.27a) and solving (2.27b): opening = Dcod to 1e-9 relative. That last check is
   !> skipped within 1% of c* = 1/2, where re-deriving the zone from c*-a* loses 1/2-c*.
   subroutine check_states(error, params, a_star, states)
      type(error_type), allocatable, intent(inout) :: error
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), intent(in) :: states(:)
      integer :: k
      do k = 1, size(states)
         call check(error, ieee_is_finite(states(k)%c_star) .and. &
            ieee_is_finite(states(k)%p_star) .and. ieee_is_finite(states(k)%gap_width), &
            "grid: non-finite state")
         call check(error, states(k)%c_star > a_star .and. states(k)%c_star <= 0.5_wp, &
            "grid: c* outside (a*, 1/2]")
         if (allocated(error) .or. states(k)%zone_case /= zone_inside) cycle
         if (k > 1) call check(error, states(k)%gap_width > states(k - 1)%gap_width, &
            "grid: case-1 roots not increasing")
         call check_close(error, md_load(params, a_star, states(k)%gap_width), &
            states(k)%p_star, 1e-10_wp, atol=1e-12_wp, what="grid: (2.27a)")
         if (0.5_wp - states(k)%c_star < 0.01_wp*(0.5_wp - a_star)) cycle
         call check_close(error, md_opening(params, a_star, states(k)%gap_width), &
            params%dcod, 1e-9_wp, what="grid: (2.27b) residual")
      end do
   end subroutine check_states

   !> One reference row: find the same state (zone, c*-a*) among md_roots' states.
   subroutine compare_row(row, zone, worst, n_bad)
      real(wp), intent(in) :: row(6)
      integer, intent(in) :: zone
      real(wp), intent(inout) :: worst(3)
      integer, intent(inout) :: n_bad
      type(params_type) :: params
      type(state_type) :: states(8)
      real(wp) :: err(3)
      integer :: status, n, k, best
      call new_params(row(1), row(2), params, status)
      call md_roots(params, row(3), states, n, status)
      best = 0
      do k = 1, min(n, size(states))
         if (states(k)%zone_case /= zone) cycle
         if (abs(states(k)%gap_width - row(5)) > 1e-6_wp*row(5)) cycle
         best = k
      end do
      if (status /= wa_ok .or. best == 0) then
         n_bad = n_bad + 1
         return
      end if
      err(1) = abs(states(best)%c_star - row(4))/row(4)
      err(2) = abs(states(best)%gap_width - row(5))/row(5)
      err(3) = abs(states(best)%p_star - row(6))/merge(abs(row(6)), 1.0_wp, abs(row(6)) >= 1e-3_wp)
      worst = max(worst, err)
   end subroutine compare_row

   !> md_options: at their defaults the state of the default call, bit for bit; the other
   !> ways to compute Psi_c (GSL's adaptive quadratures, a 64-node Gauss rule) agree with
   !> the library's rules where they work (a* = 0.25, mid-sized zone); bad options refused.
   subroutine test_options(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(state_type) :: s0, s
      type(md_options) :: opts(4)
      character(len=256) :: msg
      integer :: j, status, nres
      call new_params(0.3_wp, 1.0_wp, params, status)
      call md_equilibrium(params, 0.25_wp, s0, status)
      call check(error, status == wa_ok .and. s0%zone_case == zone_inside, "default call")
      call md_equilibrium(params, 0.25_wp, s, status, options=md_options(), n_residuals=nres)
      call check(error, status == wa_ok .and. s%c_star == s0%c_star .and. &
         s%p_star == s0%p_star .and. s%gbar == s0%gbar, "defaults not bit-identical")
      call check(error, nres >= 3 .and. nres < 200, "n_residuals")
      opts = [md_options(psi_method=md_psi_gauss, psi_nodes=64), &
         md_options(psi_method=md_psi_qaws, psi_rtol=1.0e-12_wp), &
         md_options(psi_method=md_psi_qag, psi_rtol=1.0e-12_wp), &
         md_options(psi_method=md_psi_qags, psi_rtol=1.0e-12_wp)]
      call md_prepare_options(opts(1), status)
      call check(error, status == wa_ok .and. size(opts(1)%gauss_rule, 2) == 64, "gauss rules")
      do j = 1, size(opts)
         call md_equilibrium(params, 0.25_wp, s, status, options=opts(j))
         call check(error, status == wa_ok .and. s%zone_case == zone_inside, "option: status")
         call check_close(error, s%c_star, s0%c_star, 1.0e-8_wp, what="c* by an option")
         call check_close(error, s%p_star, s0%p_star, 1.0e-8_wp, 1.0e-8_wp, "P* by an option")
      end do
      msg = ""
      call md_equilibrium(params, 0.25_wp, s, status, msg, options=md_options(psi_nodes=0))
      call check(error, status == wa_invalid_argument .and. index(msg, "psi_nodes") > 0, &
         "psi_nodes = 0 accepted")
      msg = ""
      call md_equilibrium(params, 0.25_wp, s, status, msg, options=md_options(psi_method=9))
      call check(error, status == wa_invalid_argument .and. index(msg, "psi_method") > 0, &
         "bad psi_method accepted")
   end subroutine test_options

end module test_md
