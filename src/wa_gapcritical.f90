!> Critical values under gap (mean-gap) control (issue 11 item 3; doc/theory.md, "Gap
!> control"): where the approach first feels the surface and jumps in, where contact is
!> made, the most tensile load on the retraction, and where contact and interaction are
!> lost on the retraction. All of them are states of the gap-controlled cycle of
!> wa_gappath (its events, and the folds of P* its retraction passes).
!>
!> A jump under gap control keeps gbar*: the jump-in starts and lands at g_touch (P* goes
!> from 0 to p_jump_in there), so the gbar* range where the gap law has two branches is
!> [g_touch, g_interaction_lost] (approach below, retraction above g_touch).
module wa_gapcritical
   use wa_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_negative_inf
   use wa_status, only: wa_ok, wa_invalid_argument, wa_numerical_error, set_error
   use wa_params, only: params_type, new_params
   use wa_state, only: model_jkr
   use wa_models, only: check_model
   use wa_branch, only: branch_type, trace_branch
   use wa_gappath, only: gap_path_type, gap_cycle_critical, gap_stage_approach, &
      gap_stage_retraction, gap_event_jump_start, gap_event_jump_end, &
      gap_event_contact_lost, gap_event_interaction_lost
   implicit none
   private

   public :: gap_critical_type, gap_critical, gap_critical_from_branch, gap_critical_sweep, &
      gap_critical_values, gap_critical_count, gap_critical_names

   !> Number of values of gap_critical_values (the C array WA_GAP_CRITICAL_COUNT)
   integer, parameter :: gap_critical_count = 10
   !> Their names, in order (the CLI's columns after alpha and mu)
   character(len=*), parameter :: gap_critical_names = "g_touch P_jump_in a_jump_in " // &
      "g_contact P_min g_P_min a_P_min g_contact_lost P_contact_lost g_interaction_lost"

   !> The critical values of one gap-controlled cycle.
   type :: gap_critical_type
      !> Approach: gbar* of the first interaction (P* = 0 above it; 1 except for MD)
      real(wp) :: g_touch = 1.0_wp
      !> P* and a* where the approach lands when it jumps at g_touch (0 and 0: no jump,
      !> the approach leaves P* = 0 gradually; MD: a* = 0 when it lands on the states
      !> without contact)
      real(wp) :: p_jump_in = 0.0_wp, a_jump_in = 0.0_wp
      !> gbar* where contact is first made on the approach (g_touch except for MD)
      real(wp) :: g_contact = 1.0_wp
      !> On the retraction, the most tensile load, with its gbar* and a* (JKR: -Infinity at
      !> gbar* = 0, full contact never releases a finite load)
      real(wp) :: p_min = 0.0_wp, g_p_min = 0.0_wp, a_p_min = 0.0_wp
      !> gbar* where contact is lost for good on the retraction (MD can lose and regain
      !> contact: the last loss), and P* of the last state with contact there
      real(wp) :: g_contact_lost = 1.0_wp, p_contact_lost = 0.0_wp
      !> gbar* where the interaction is lost (P* = 0 above it)
      real(wp) :: g_interaction_lost = 1.0_wp
   end type gap_critical_type

contains

   !> Trace the branch and follow the gap-controlled cycle; its critical values.
   subroutine gap_critical(model, params, crit, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(gap_critical_type), intent(out) :: crit
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      call check_model(model, status, errmsg)
      if (status /= wa_ok) return
      call trace_branch(model, params, branch, status, errmsg)
      if (status /= wa_ok) return
      call gap_critical_from_branch(model, params, branch, crit, status, errmsg)
   end subroutine gap_critical

   !> The critical values on a traced branch (the gap_path of the same branch holds each
   !> of them as an event, p_min excepted where it is a fold of P*).
   subroutine gap_critical_from_branch(model, params, branch, crit, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(gap_critical_type), intent(out) :: crit
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(gap_path_type) :: path
      integer :: k
      logical :: lost, now

      call gap_cycle_critical(model, params, branch, path, crit%p_min, crit%g_p_min, &
         crit%a_p_min, crit%g_contact, status, errmsg)
      if (status /= wa_ok) return
      if (model == model_jkr) then                   ! P* -> -Infinity as a* -> 1/2
         crit%p_min = ieee_value(1.0_wp, ieee_negative_inf)
         crit%g_p_min = 0.0_wp
         crit%a_p_min = 0.5_wp
      end if
      crit%g_touch = path%g_touch
      ! the jump-in: the approach's second event is a jump from the P* = 0 states
      if (path%n >= 3) then
         if (path%stage(2) == gap_stage_approach .and. path%event(2) == gap_event_jump_start &
            .and. path%p_star(2) == 0.0_wp .and. path%c_star(2) == 0.0_wp) then
            crit%p_jump_in = path%p_star(3)
            crit%a_jump_in = path%a_star(3)
         end if
      end if
      lost = .false.                                 ! the last loss of contact counts
      do k = 1, path%n
         if (path%stage(k) /= gap_stage_retraction) cycle
         now = path%event(k) == gap_event_contact_lost
         if (k < path%n .and. path%event(k) == gap_event_jump_start .and. &
            path%a_star(k) > 0.0_wp) now = path%event(k + 1) == gap_event_jump_end .and. &
            path%a_star(k + 1) == 0.0_wp
         if (now) then
            lost = .true.
            crit%g_contact_lost = path%gbar(k)
            crit%p_contact_lost = path%p_star(k)
         end if
         if (path%event(k) == gap_event_interaction_lost) crit%g_interaction_lost = path%gbar(k)
      end do
      if (.not. lost) call set_error(wa_numerical_error, "gap_critical: the retraction "// &
         "does not lose contact", status, errmsg)
   end subroutine gap_critical_from_branch

   !> The values of crit in the order of gap_critical_names.
   pure function gap_critical_values(crit) result(v)
      type(gap_critical_type), intent(in) :: crit
      real(wp) :: v(gap_critical_count)
      v = [crit%g_touch, crit%p_jump_in, crit%a_jump_in, crit%g_contact, crit%p_min, &
         crit%g_p_min, crit%a_p_min, crit%g_contact_lost, crit%p_contact_lost, &
         crit%g_interaction_lost]
   end function gap_critical_values

   !> gap_critical for one alpha over the values mu(:): values(:, i) (gap_critical_values)
   !> of row i. Model and alpha are checked first (an invalid one: status, every value
   !> NaN, nothing computed). A row whose mu is invalid or whose cycle fails gets NaN
   !> values and its status in row_status (and its message in row_errmsg); every other
   !> row is computed, and status/errmsg are those of the first failing row (its mu and
   !> the number of failing rows in the message).
   subroutine gap_critical_sweep(model, alpha, mu, values, status, errmsg, row_status, &
         row_errmsg)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu(:)
      !> (gap_critical_count, size(mu))
      real(wp), intent(out) :: values(:, :)
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, intent(out), optional :: row_status(:)
      character(len=*), intent(out), optional :: row_errmsg(:)
      type(params_type) :: params
      type(gap_critical_type) :: crit
      character(len=256) :: msg, first_msg
      character(len=24) :: t_mu, t_n, t_all
      real(wp) :: first_mu
      integer :: i, stat, first_stat, n_failed

      values = ieee_value(1.0_wp, ieee_quiet_nan)
      if (present(row_status)) row_status = wa_ok
      if (present(row_errmsg)) row_errmsg = ""
      if (size(values, 1) /= gap_critical_count .or. size(values, 2) /= size(mu)) then
         call set_error(wa_invalid_argument, "gap_critical_sweep: values must have the shape "// &
            "(gap_critical_count, size(mu))", status, errmsg)
         if (present(row_status)) row_status = status
         return
      end if
      msg = ""
      call check_model(model, status, msg)
      if (status == wa_ok) call new_params(alpha, 0.0_wp, params, status, msg)
      if (status /= wa_ok) then
         if (present(errmsg)) errmsg = msg
         if (present(row_status)) row_status = status
         return
      end if
      first_stat = wa_ok
      n_failed = 0
      first_mu = 0.0_wp
      first_msg = ""
      do i = 1, size(mu)
         msg = ""
         call new_params(alpha, mu(i), params, stat, msg)
         if (stat == wa_ok) call gap_critical(model, params, crit, stat, msg)
         if (present(row_status)) row_status(i) = stat
         if (stat == wa_ok) then
            values(:, i) = gap_critical_values(crit)
            cycle
         end if
         if (present(row_errmsg)) row_errmsg(i) = msg
         n_failed = n_failed + 1
         if (n_failed == 1) then
            first_stat = stat
            first_msg = msg
            first_mu = mu(i)
         end if
      end do
      status = wa_ok
      if (n_failed > 0) then
         write (t_mu, '(es12.5)') first_mu
         write (t_n, '(i0)') n_failed
         write (t_all, '(i0)') size(mu)
         call set_error(first_stat, "mu = "//trim(adjustl(t_mu))//": "//trim(first_msg)// &
            " ("//trim(t_n)//" of "//trim(t_all)//" rows failed; their values are NaN)", &
            status, errmsg)
      end if
   end subroutine gap_critical_sweep

end module wa_gapcritical
