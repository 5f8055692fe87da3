!> Critical values under gap control (src/wa_gapcritical.f90, issue 11 item 3): each is
!> a state of gap_path's cycle (its events), the most tensile load on the retraction is
!> the load-control pull-off P_pf (and no sampled retraction state of the gap law is more
!> tensile), Westergaard has no jump and touches and separates at gbar* = 1, JKR's most
!> tensile load is -Infinity; bad input gives a status and NaN rows. P_min is the least P*
!> of every state the retraction passes (against gap_law's retraction, and the model's
!> roots below the tracer's first point) at small alpha too; the gbar* are ordered down
!> to alpha = 1e-12.
module test_gapcritical
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use wavyadhesion
   use wa_kinds, only: wp
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   use test_gappath, only: roots_extremum
   implicit none
   private

   public :: collect_gapcritical

   real(wp), parameter :: alphas(2) = [0.3_wp, 1.0_wp], mus(4) = [0.1_wp, 0.3_wp, 1.0_wp, 5.0_wp]

contains

   subroutine collect_gapcritical(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("values_are_path_events", test_events), &
         new_unittest("p_min_is_load_control_pull_off", test_pull_off), &
         new_unittest("p_min_against_gap_law", test_gap_law), &
         new_unittest("westergaard", test_westergaard), &
         new_unittest("jkr_p_min_infinite", test_jkr), &
         new_unittest("sweep_bad_input", test_sweep_bad_input), &
         new_unittest("p_min_small_alpha_against_gap_law", test_small_alpha_law), &
         new_unittest("p_min_fold_below_tracer_floor", test_fold_below_floor), &
         new_unittest("gbar_order_tiny_alpha", test_order_tiny_alpha)]
   end subroutine collect_gapcritical

   subroutine both(model, alpha, mu, crit, path, error)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu
      type(gap_critical_type), intent(out) :: crit
      type(gap_path_type), intent(out) :: path
      type(error_type), allocatable, intent(inout) :: error
      type(params_type) :: params
      integer :: status
      character(len=256) :: msg
      msg = ""
      call new_params(alpha, mu, params, status)
      call gap_critical(model, params, crit, status, msg)
      call check(error, status == wa_ok, "gap_critical failed: "//trim(msg))
      call gap_path(model, params, path, status, msg)
      call check(error, status == wa_ok, "gap_path failed: "//trim(msg))
   end subroutine both

   !> g_touch, the jump-in, contact made and lost, interaction lost: the path's events.
   subroutine test_events(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      integer :: m, j, i, k, last_loss, models(2)
      models = [model_dw, model_md]
      do m = 1, 2
         do j = 1, size(alphas)
            do i = 1, size(mus)
               call both(models(m), alphas(j), mus(i), crit, path, error)
               if (allocated(error)) return
               call check(error, crit%g_touch == path%g_touch .and. &
                  crit%g_touch == path%gbar(1), "g_touch is the touch event")
               call check(error, crit%g_interaction_lost == path%gbar(path%n) .and. &
                  path%event(path%n) == gap_event_interaction_lost, "interaction lost")
               if (path%event(2) == 3) then               ! a jump-in at g_touch
                  call check(error, crit%p_jump_in == path%p_star(3) .and. &
                     crit%a_jump_in == path%a_star(3) .and. crit%p_jump_in < 0.0_wp, &
                     "the jump-in lands on the path's event")
                  call check_close(error, path%gbar(3), crit%g_touch, 1.0e-10_wp, &
                     what="the jump-in keeps gbar*")
               else
                  call check(error, crit%p_jump_in == 0.0_wp, "no jump-in: P_jump_in = 0")
               end if
               last_loss = 0
               do k = 1, path%n - 1
                  if (path%stage(k) /= gap_stage_retraction) cycle
                  if (path%event(k) == gap_event_contact_lost .or. (path%event(k) == 3 .and. &
                     path%a_star(k) > 0.0_wp .and. path%a_star(k + 1) == 0.0_wp)) last_loss = k
               end do
               call check(error, last_loss > 0, "the retraction loses contact")
               if (allocated(error)) return
               call check(error, crit%g_contact_lost == path%gbar(last_loss) .and. &
                  crit%p_contact_lost == path%p_star(last_loss), "contact lost: the event")
               call check(error, crit%g_contact <= crit%g_touch .and. &
                  crit%g_contact_lost <= crit%g_interaction_lost, "order of the gbar*")
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_events

   !> Both controls leave full contact along the same states until the load-control
   !> jump that ends in pull-off starts at a fold or corner; gap control passes through
   !> it, so P_min <= P_pf; on this grid they are the same state (1e-12).
   subroutine test_pull_off(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      type(params_type) :: params
      real(wp) :: p_fc, p_pf
      integer :: m, j, i, k, status, models(2)
      models = [model_dw, model_md]
      do m = 1, 2
         do j = 1, size(alphas)
            do i = 1, size(mus)
               call both(models(m), alphas(j), mus(i), crit, path, error)
               call new_params(alphas(j), mus(i), params, status)
               call critical_forces(models(m), params, p_fc, p_pf, status)
               call check(error, status == wa_ok, "critical_forces")
               call check_close(error, crit%p_min, p_pf, 1.0e-12_wp, 1.0e-15_wp, &
                  what="P_min = P_pf")
               do k = 1, path%n
                  if (path%stage(k) == gap_stage_retraction) call check(error, &
                     path%p_star(k) >= crit%p_min, "P_min below every retraction event")
               end do
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_pull_off

   !> The gap law on retraction at gbar*(P_min) is P_min, and on 2001 gbar* from 0 to
   !> g_interaction_lost no retraction state is more tensile.
   subroutine test_gap_law(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      type(params_type) :: params
      real(wp) :: g(2001), pa(2001), pr(2001), da(2001), dr(2001)
      integer :: m, i, k, status, models(2)
      character(len=256) :: msg
      models = [model_dw, model_md]
      do m = 1, 2
         do i = 2, size(mus)
            call both(models(m), 0.3_wp, mus(i), crit, path, error)
            if (allocated(error)) return
            call new_params(0.3_wp, mus(i), params, status)
            g = [(crit%g_interaction_lost*real(k, wp)/2000.0_wp, k = 0, 2000)]
            g(1) = crit%g_p_min
            call gap_law(models(m), params, g, pa, pr, da, dr, status, msg)
            call check(error, status == wa_ok, "gap_law: "//trim(msg))
            call check_close(error, pr(1), crit%p_min, 1.0e-9_wp, 1.0e-12_wp, &
               what="gap law at gbar*(P_min)")
            call check(error, minval(pr) >= crit%p_min - 1.0e-12_wp, &
               "a sampled retraction state more tensile than P_min")
            if (allocated(error)) return
         end do
      end do
   end subroutine test_gap_law

   !> Westergaard: touch and contact at gbar* = 1 without a jump, contact and interaction
   !> lost at gbar* = 1 (P* -> 0 as a* -> 0: no hysteresis), P_min = 0 there.
   subroutine test_westergaard(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      call both(model_westergaard, 0.3_wp, 1.0_wp, crit, path, error)
      if (allocated(error)) return
      call check(error, crit%g_touch == 1.0_wp .and. crit%p_jump_in == 0.0_wp .and. &
         crit%a_jump_in == 0.0_wp .and. crit%g_contact == 1.0_wp, "approach")
      call check(error, crit%g_contact_lost == 1.0_wp .and. crit%g_interaction_lost == &
         1.0_wp .and. crit%p_min == 0.0_wp .and. crit%g_p_min == 1.0_wp, "retraction")
      call check_close(error, crit%p_contact_lost, 0.0_wp, 0.0_wp, 1.0e-25_wp, &
         what="P* where contact is lost")
   end subroutine test_westergaard

   !> JKR: P* -> -Infinity at full contact, where the retraction starts.
   subroutine test_jkr(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      call both(model_jkr, 0.3_wp, 1.0_wp, crit, path, error)
      if (allocated(error)) return
      call check(error, .not. ieee_is_finite(crit%p_min) .and. crit%p_min < 0.0_wp .and. &
         crit%g_p_min == 0.0_wp, "JKR P_min = -Infinity at gbar* = 0")
      call check(error, crit%g_touch == 1.0_wp .and. crit%p_jump_in < 0.0_wp, "JKR jumps in")
   end subroutine test_jkr

   !> A bad mu fails its row only (NaN, status, message naming mu); a bad alpha or model
   !> fails everything before any work; an empty mu is fine; a wrong shape is refused.
   subroutine test_sweep_bad_input(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: v(gap_critical_count, 3), nan_mu
      integer :: status, rows(3)
      character(len=256) :: msg, row_msg(3)
      nan_mu = 0.0_wp
      nan_mu = nan_mu/nan_mu
      msg = ""
      call gap_critical_sweep(model_dw, 0.3_wp, [1.0_wp, -1.0_wp, nan_mu], v, status, msg, &
         rows, row_msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "mu") > 0 .and. &
         index(msg, "2 of 3 rows") > 0, "status and message: "//trim(msg))
      call check(error, all(rows == [wa_ok, wa_invalid_argument, wa_invalid_argument]), &
         "row statuses")
      call check(error, all(ieee_is_finite(v(:, 1))) .and. all(ieee_is_nan(v(:, 2:3))), &
         "good row kept, bad rows NaN")
      call check(error, index(row_msg(2), "[1e-100, 1e100]") > 0, "row message: "// &
         trim(row_msg(2)))
      call gap_critical_sweep(model_dw, -0.3_wp, [1.0_wp, 2.0_wp, 3.0_wp], v, status, msg, rows)
      call check(error, status == wa_invalid_argument .and. index(msg, "alpha") > 0 .and. &
         all(ieee_is_nan(v)) .and. all(rows == wa_invalid_argument), "bad alpha: "//trim(msg))
      call gap_critical_sweep(9, 0.3_wp, [1.0_wp, 2.0_wp, 3.0_wp], v, status, msg)
      call check(error, status == wa_invalid_argument .and. all(ieee_is_nan(v)), "bad model")
      call gap_critical_sweep(model_dw, 0.3_wp, [1.0_wp, 2.0_wp], v, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "shape") > 0, &
         "wrong shape: "//trim(msg))
      call gap_critical_sweep(model_dw, 0.3_wp, [real(wp) ::], v(:, 1:0), status, msg)
      call check(error, status == wa_ok, "empty mu")
   end subroutine test_sweep_bad_input

   !> gap_critical and gap_path, where the branch can be traced (ok = .false. if not: the
   !> tracer's failures at small alpha are not what these tests are about)
   subroutine try_both(model, alpha, mu, crit, path, ok, error)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu
      type(gap_critical_type), intent(out) :: crit
      type(gap_path_type), intent(out) :: path
      logical, intent(out) :: ok
      type(error_type), allocatable, intent(inout) :: error
      type(params_type) :: params
      type(branch_type) :: b
      integer :: status
      call new_params(alpha, mu, params, status)
      call trace_branch(model, params, b, status)
      ok = status == wa_ok
      if (ok) call both(model, alpha, mu, crit, path, error)
   end subroutine try_both

   !> The least P* of gap_law's retraction: on the gbar* of the retraction's events, 1000
   !> points up to g_interaction_lost and 1000 clustered below it, then twice on 2001
   !> points around the least one.
   subroutine law_minimum(model, params, path, g_end, p_law, status)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(gap_path_type), intent(in) :: path
      real(wp), intent(in) :: g_end
      real(wp), intent(out) :: p_law
      integer, intent(out) :: status
      integer, parameter :: n = 2001
      real(wp) :: g(n), pa(n), pr(n), da(n), dr(n), lo, hi
      integer :: k, m, zoom
      m = 0
      do k = 1, path%n
         if (path%stage(k) /= gap_stage_retraction .or. m >= 64) cycle
         m = m + 1
         g(m) = path%gbar(k)
      end do
      do k = m + 1, n
         if (mod(k, 2) == 0) then
            g(k) = g_end*real(k - m, wp)/real(n - m, wp)
         else
            g(k) = g_end*(1.0_wp - 10.0_wp**(-14.0_wp*real(k - m, wp)/real(n - m, wp)))
         end if
      end do
      p_law = 0.0_wp
      do zoom = 1, 3
         call gap_law(model, params, g, pa, pr, da, dr, status)
         if (status /= wa_ok) return
         k = minloc(pr, 1)
         p_law = pr(k)
         lo = minval(g); hi = maxval(g)              ! the neighbouring gbar* of the grid
         do m = 1, n
            if (g(m) < g(k) .and. g(m) > lo) lo = g(m)
            if (g(m) > g(k) .and. g(m) < hi) hi = g(m)
         end do
         lo = min(lo, g(k)); hi = max(hi, g(k))
         g = [(lo + (hi - lo)*real(m - 1, wp)/real(n - 1, wp), m = 1, n)]
      end do
   end subroutine law_minimum

   !> Issue item 1: below alpha ~ 1e-3 a fold of P* can lie within one node of the gbar*
   !> maximum the retraction jumps from; P_min was the jump's start, up to 2 % less
   !> tensile. On alpha in {1e-7 ... 1e-3} x mu (DW, MD), the two reproducers included,
   !> P_min is gap_law's least retraction P* (1e-6, 1e-14 absolute: the law's accuracy at
   !> P* ~ 1e-11) and, for the reproducers, critical_forces' P_pf (the same fold).
   subroutine test_small_alpha_law(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: al(4) = [1.0e-7_wp, 1.0e-6_wp, 3.0e-5_wp, 1.0e-3_wp]
      real(wp), parameter :: mu_grid(4) = [0.91_wp, 1.2068_wp, 7.684_wp, 843.7_wp]
      integer, parameter :: rep_model(2) = [model_dw, model_md]
      real(wp), parameter :: rep_alpha(2) = [3.2953421004685887e-05_wp, &
         1.5974167225652566e-05_wp]
      real(wp), parameter :: rep_mu(2) = [843.70633645969394_wp, 7.6839020263374715_wp]
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      type(params_type) :: params
      real(wp) :: p_law, p_fc, p_pf
      integer :: m, j, i, status, models(2), n_done
      logical :: ok
      models = [model_dw, model_md]
      n_done = 0
      do m = 1, 2
         do j = 1, size(al)
            do i = 1, size(mu_grid)
               call compare(models(m), al(j), mu_grid(i))
               if (allocated(error)) return
            end do
         end do
      end do
      call check(error, n_done >= 26, "most of the grid traced")
      do m = 1, 2
         call compare(rep_model(m), rep_alpha(m), rep_mu(m))
         call check(error, ok, "reproducer traced")
         if (allocated(error)) return
         call critical_forces(rep_model(m), params, p_fc, p_pf, status)
         call check_close(error, crit%p_min, p_pf, 1.0e-12_wp, what="reproducer: P_min = P_pf")
         if (allocated(error)) return
      end do
   contains
      subroutine compare(model, alpha, mu)
         integer, intent(in) :: model
         real(wp), intent(in) :: alpha, mu
         character(len=80) :: what
         call try_both(model, alpha, mu, crit, path, ok, error)
         if (allocated(error) .or. .not. ok) return
         n_done = n_done + 1
         call new_params(alpha, mu, params, status)
         call law_minimum(model, params, path, crit%g_interaction_lost, p_law, status)
         call check(error, status == wa_ok, "gap_law")
         write (what, '(a,i2,2es12.4)') "P_min = gap law's minimum: model, alpha, mu", &
            model, alpha, mu
         call check_close(error, crit%p_min, p_law, 1.0e-6_wp, 1.0e-14_wp, what=trim(what))
      end subroutine compare
   end subroutine test_small_alpha_law

   !> Below the tracer's first point a* = 1e-6 P* - P*(0) ~ a*^2 (k1 ln a* + k2) can have a
   !> minimum: DW and MD at alpha 1e-7, mu 0.91, at a* ~ 3.5e-7, 1.2e-3 (DW) more tensile
   !> than P* at a* -> 0, which P_min was. Against the least P* of the model's roots
   !> (roots_extremum, golden sections in ln a* over [1e-10, 1e-5], the root of least c*).
   subroutine test_fold_below_floor(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      type(params_type) :: params
      type(state_type) :: low
      integer :: m, status, models(2)
      logical :: ok
      models = [model_dw, model_md]
      do m = 1, 2
         call both(models(m), 1.0e-7_wp, 0.91029817799152157_wp, crit, path, error)
         if (allocated(error)) return
         call new_params(1.0e-7_wp, 0.91029817799152157_wp, params, status)
         call roots_extremum(models(m), params, 1.0e-10_wp, 1.0e-5_wp, 0.0_wp, 2, low, ok)
         call check(error, ok, "roots scan")
         call check_close(error, crit%p_min, low%p_star, 1.0e-10_wp, what="P_min below a_start")
         call check(error, crit%a_p_min > 1.0e-8_wp .and. crit%a_p_min < 1.0e-6_wp, &
            "the fold lies below the tracer's first point")
         if (allocated(error)) return
      end do
   end subroutine test_fold_below_floor

   !> Issue item 5c: at alpha = 1e-12 the cycle's gbar* lie within a few ulps of 1 (MD:
   !> g_contact was 1 + 6 ulps > g_touch). A plateau of equal gbar* at a maximum of the
   !> chain hid it, and the walk ran uphill. Down to alpha = 1e-12 (DW, MD) the contracts
   !> hold exactly: g_contact <= g_touch <= g_interaction_lost, g_P_min <= g_contact_lost
   !> <= g_interaction_lost, the approach's events never rise in gbar*, the retraction's
   !> never fall.
   subroutine test_order_tiny_alpha(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: al(4) = [1.0e-12_wp, 1.0e-11_wp, 1.0e-10_wp, 1.0e-8_wp]
      real(wp), parameter :: mu_grid(4) = [0.21544346900318823_wp, 1.0_wp, &
         2.1544346900318821_wp, 6.3_wp]
      type(gap_critical_type) :: crit
      type(gap_path_type) :: path
      integer :: m, j, i, k, models(2), n_done
      character(len=80) :: what
      logical :: ok
      models = [model_dw, model_md]
      n_done = 0
      do m = 1, 2
         do j = 1, size(al)
            do i = 1, size(mu_grid)
               call try_both(models(m), al(j), mu_grid(i), crit, path, ok, error)
               if (allocated(error)) return
               if (.not. ok) cycle
               n_done = n_done + 1
               write (what, '(a,i2,2es12.4)') "order of the gbar*: model, alpha, mu", &
                  models(m), al(j), mu_grid(i)
               call check(error, crit%g_contact <= crit%g_touch .and. crit%g_touch <= &
                  crit%g_interaction_lost .and. crit%g_p_min <= crit%g_contact_lost .and. &
                  crit%g_contact_lost <= crit%g_interaction_lost, trim(what))
               do k = 2, path%n
                  if (path%stage(k) /= path%stage(k - 1)) cycle
                  if (path%stage(k) == gap_stage_approach) then
                     call check(error, path%gbar(k) <= path%gbar(k - 1), "approach: "//trim(what))
                  else
                     call check(error, path%gbar(k) >= path%gbar(k - 1), &
                        "retraction: "//trim(what))
                  end if
               end do
               if (allocated(error)) return
            end do
         end do
      end do
      call check(error, n_done >= 20, "most of the grid traced")
   end subroutine test_order_tiny_alpha

end module test_gapcritical
