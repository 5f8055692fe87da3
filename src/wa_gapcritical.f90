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
   use wa_state, only: state_type, model_jkr
   use wa_models, only: check_model
   use wa_branch, only: branch_type, trace_branch
   use wa_roots, only: golden_type, golden_init, golden_propose, golden_accept
   use wa_chain, only: chain_type, stretch_type, chain_state, param_kind, param, &
      below_tracer, state_at_param
   use wa_gappath, only: gap_path_type, walk_cycle, max_walked, gap_stage_approach, &
      gap_stage_retraction, gap_event_jump_start, gap_event_jump_end, &
      gap_event_contact_lost, gap_event_interaction_lost, gap_event_contact_made
   implicit none
   private

   public :: gap_critical_type, gap_critical, gap_critical_from_branch, gap_critical_sweep, &
      gap_critical_values, gap_critical_count, gap_critical_names
   public :: gap_cycle_critical

   !> Number of values of gap_critical_values (the C array WA_GAP_CRITICAL_COUNT)
   integer, parameter :: gap_critical_count = 10
   !> Their names, in order (the CLI's columns after alpha and mu)
   character(len=*), parameter :: gap_critical_names = "g_touch P_jump_in a_jump_in " // &
      "g_contact P_min g_P_min a_P_min g_contact_lost P_contact_lost g_interaction_lost"

   !> The critical values of one gap-controlled cycle.
   type :: gap_critical_type
      !> On the approach, gbar* of the first interaction (P* = 0 above it; 1 except for MD)
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
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The critical values of the gap-controlled cycle
      type(gap_critical_type), intent(out) :: crit
      !> wa_ok; wa_invalid_argument for a bad model; else the status of the failing trace
      !> or cycle
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
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
      !> The critical values of one cycle (gap_critical)
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
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> The adhesion parameter alpha (valid range: new_params)
      real(wp), intent(in) :: alpha
      !> The values of the elasticity parameter mu, one row each
      real(wp), intent(in) :: mu(:)
      !> (gap_critical_count, size(mu))
      real(wp), intent(out) :: values(:, :)
      !> wa_ok; the status of the bad model or alpha, or of the first failing row
      integer, intent(out) :: status
      !> Receives the reason on failure (the first failing row's mu and message, and the
      !> number of failing rows)
      character(len=*), intent(inout), optional :: errmsg
      !> The status of each row (size of mu)
      integer, intent(out), optional :: row_status(:)
      !> The message of each failing row (blank for the others; size of mu)
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

   ! ------------------------------------------ the cycle's extreme states

   !> The events of the gap-controlled cycle (as gap_path, without W*: path%w_star = 0),
   !> the most tensile load on the retraction, p_min, with its gbar* and a*, and
   !> g_contact, the gbar* where contact (a* > 0, or MD's contact-made event) is first
   !> made on the approach.
   !> Invariant: p_min is the minimum of P* over every state the retraction passes, the
   !> end points of its jumps included. Along a walked stretch P* is extremal only at a
   !> fold of P* (a point of the traced branch, located to ~1e-11 in a*) or at a corner
   !> (a point too), so the minimum is taken over the retraction's events, the chain
   !> points its stretches cover, and the traced points that the refinement of a gbar*
   !> extremum replaced where its stretches cover their positions (at small alpha a fold
   !> of P* lies within one node of the gbar* maximum the retraction jumps from: it used
   !> to be lost, and P_min was the jump's start, up to 2 % less tensile).
   subroutine gap_cycle_critical(model, params, branch, path, p_min, g_min, a_min, g_contact, &
         status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(gap_path_type), intent(out) :: path
      real(wp), intent(out) :: p_min, g_min, a_min, g_contact
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(chain_type) :: ch
      type(stretch_type) :: walked(max_walked)
      type(state_type) :: s
      integer :: n_walked, n_approach, k, i
      real(wp) :: lo, hi, g_end

      p_min = huge(1.0_wp); g_min = 0.0_wp; a_min = 0.0_wp; g_contact = -1.0_wp
      call walk_cycle(model, params, branch, ch, path, walked, n_walked, n_approach, &
         status, errmsg)
      if (status /= wa_ok) return
      if (.not. ch%joined) g_contact = path%g_touch  ! the chain is all contact states
      do k = 1, path%n
         if (path%stage(k) == gap_stage_approach .and. g_contact < 0.0_wp .and. &
            (path%event(k) == gap_event_contact_made .or. path%a_star(k) > 0.0_wp)) &
            g_contact = path%gbar(k)
         if (path%stage(k) /= gap_stage_retraction) cycle
         if (path%p_star(k) < p_min) then
            p_min = path%p_star(k); g_min = path%gbar(k); a_min = path%a_star(k)
         end if
      end do
      do k = n_approach + 1, n_walked
         lo = min(walked(k)%s1, walked(k)%s2)
         hi = max(walked(k)%s1, walked(k)%s2)
         do i = max(1, ceiling(lo) + 1), min(ch%n, floor(hi) + 1)
            if (ch%p(i) < p_min) then
               p_min = ch%p(i); g_min = ch%g(i); a_min = ch%a(i)
            end if
         end do
         ! the stretch ends at a chain point, its largest gbar*: a state beyond it is not
         ! passed (where round-off hides a turn of gbar*, alpha below ~1e-10)
         g_end = ch%g(nint(walked(k)%s2) + 1)
         do i = 1, ch%n_moved                        ! traced points a refinement replaced
            if (ch%moved_s(i) >= lo .and. ch%moved_s(i) <= hi .and. ch%moved_p(i) < p_min &
               .and. ch%moved_g(i) <= g_end) then
               p_min = ch%moved_p(i); g_min = ch%moved_g(i); a_min = ch%moved_a(i)
            end if
         end do
         do i = max(1, int(lo) + 1), min(ch%n - 1, ceiling(hi))   ! intervals below a_start
            if (.not. below_tracer(ch, i) .or. hi <= real(i - 1, wp) .or. lo >= real(i, wp)) &
               cycle
            call floor_minimum(model, params, ch, i, max(lo - real(i - 1, wp), 0.0_wp), &
               min(hi - real(i - 1, wp), 1.0_wp), s, status, errmsg)
            if (status /= wa_ok) return
            if (s%p_star < p_min .and. s%gbar <= g_end) then
               p_min = s%p_star; g_min = s%gbar; a_min = s%a_star
            end if
         end do
      end do
      if (.not. (p_min < huge(1.0_wp) .and. g_contact >= 0.0_wp)) call set_error( &
         wa_numerical_error, "gap_path: the cycle has no retraction or makes no contact", &
         status, errmsg)
   end subroutine gap_cycle_critical

   !> The state of least P* on chain interval i between t0 and t1 (a below_tracer
   !> interval). There P* - P*(a* -> 0) ~ a*^2 (k1 ln a* + k2) (doc/theory.md), which can
   !> have a minimum, a fold of P* that no traced point shows (DW, alpha = 1e-7, mu = 0.91:
   !> at a* ~ 3.5e-7, 1.2e-3 more tensile than P*(a* -> 0)). That form is unimodal in
   !> ln a*: golden sections in ln a* over a* >= 1e-9 of the upper end (a minimum further
   !> down is below 1e-18 of P*'s variation over the interval), to 1e-6 in ln a*
   !> (P* to ~1e-12 of that variation), or in the curve variable y where that is the
   !> interval's parameter (a* steep in it), to 1e-9 of its range. Where the sections
   !> close on an end of the range, P* is monotone there: s is the better end point of
   !> the interval (a chain point, as solved by the tracer).
   subroutine floor_minimum(model, params, ch, i, t0, t1, s, status, errmsg)
      integer, intent(in) :: model, i
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: t0, t1
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: st(2), s1
      type(golden_type) :: gs
      real(wp) :: ua, ub, x, a_lo, a_hi, tol, u_first, u_last
      integer :: it, slot
      logical :: in_log, done, moved

      status = wa_ok
      in_log = param_kind(ch, i) == 0
      a_lo = min(param(ch, i, t0), param(ch, i, t1))
      a_hi = max(param(ch, i, t0), param(ch, i, t1))
      s = chain_state(ch, i)
      if (ch%p(i + 1) < s%p_star) s = chain_state(ch, i + 1)
      if (in_log) then
         if (.not. (a_hi > 0.0_wp)) return
         ua = log(max(a_lo, 1.0e-9_wp*a_hi)); ub = log(a_hi)
         tol = 1.0e-6_wp
      else
         ua = a_lo; ub = a_hi
         tol = 1.0e-9_wp*(ub - ua)
      end if
      if (.not. (ub > ua)) return
      u_first = ua; u_last = ub
      call golden_init(gs, ua, ub, tol, 0.0_wp)
      do it = 1, 102                          ! the two first points and 100 sections
         call golden_propose(gs, x, done, slot, moved)
         if (done) exit
         if (moved) st(3 - slot) = st(slot)
         call solve(x, st(slot))
         if (status /= wa_ok) return
         call golden_accept(gs, st(slot)%p_star)
      end do
      ! an interior minimum only (both ends of the bracket moved), below the ends by more
      ! than the round-off of the point solves; else P* is monotone (or flat) over the
      ! range and its least value is the end's, a chain point
      if (gs%lo == u_first .or. gs%hi == u_last) return
      s1 = st(1)
      if (st(2)%p_star < st(1)%p_star) s1 = st(2)
      if (s1%p_star < s%p_star - 16.0_wp*epsilon(1.0_wp)*abs(s%p_star)) s = s1
   contains
      subroutine solve(u, st)
         real(wp), intent(in) :: u
         type(state_type), intent(out) :: st
         if (in_log) then
            call state_at_param(model, params, ch, i, exp(u), st, status, errmsg)
         else
            call state_at_param(model, params, ch, i, u, st, status, errmsg)
         end if
      end subroutine solve
   end subroutine floor_minimum

end module wa_gapcritical
