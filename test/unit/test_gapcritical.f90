!> Critical values under gap control (src/wa_gapcritical.f90, issue 11 item 3): each is
!> a state of gap_path's cycle (its events), the most tensile load on the retraction is
!> the load-control pull-off P_pf (and no sampled retraction state of the gap law is more
!> tensile), Westergaard has no jump and touches and separates at gbar* = 1, JKR's most
!> tensile load is -Infinity; bad input gives a status and NaN rows.
module test_gapcritical
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use wavyadhesion
   use wa_kinds, only: wp
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
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
         new_unittest("sweep_bad_input", test_sweep_bad_input)]
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
               call check(error, crit%g_contact <= crit%g_touch*(1.0_wp + 1.0e-14_wp) .and. &
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

end module test_gapcritical
