!> Pseudo-arclength continuation of the equilibrium curve P*(a*), c*(a*) of the cohesive
!> models over 0 < a* < 1/2, through every fold, with the zone-case switches (c* reaching
!> 1/2 and leaving it) and the folds of P* (dP*/da* = 0) located as events; the closed
!> forms (Westergaard, JKR) sampled with their folds.
!>
!> The case-1 curve is the zero set of one residual F(a*, y) (y: the model's zone
!> variable, wa_curve); it is followed in the plane z = (a*, w y) with a tangent
!> predictor and a Newton corrector on the arclength-augmented system
!>   F(z) = 0,  t . (z - z_pred) = 0
!> (one step and the events within it: wa_branch_step), with steps adapted to the
!> corrector's convergence and to the turn of the tangent. Case 2 (c* = 1/2) is explicit
!> in a*; it holds where F(a*, y_max) < 0. The points go into a branch_type
!> (wa_branch_types).
module wa_branch
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_not_converged, wa_numerical_error, set_error
   use wa_params, only: params_type, check_params
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact, &
      model_westergaard, model_jkr, model_dw, model_md
   use wa_curve, only: curve_residual, curve_state, curve_y_max, curve_weight, &
      curve_case2_load, curve_variable, curve_equilibrium
   use wa_models, only: check_model, model_roots, model_equilibrium, max_model_roots
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_separation, only: state_mean_gap, dw_state_gbar, md_state_gbar
   use wa_md_nocontact, only: md_no_contact_family
   use wa_branch_types, only: branch_type, trace_options, append, reserve
   use wa_branch_step, only: curve_point, corrector, orient, locate_zero, crosses_case2, &
      case1_extremum, switch_abscissa, case2_point, case2_slope, corner_extremum
   implicit none
   private

   public :: trace_branch
   !> trace_branch's argument types, for its callers
   public :: branch_type, trace_options
   public :: event_none, event_fold, event_switch, event_jump_start, event_jump_end, &
      event_full_contact_reached, event_full_contact_left, event_pull_off, event_branch_end, &
      event_a_turn

   !> Event codes (the CLI's and C header's): 0 none, 1 fold of P*, 2 zone-case switch,
   !> 3 jump start, 4 jump end, 5 full contact reached, 6 full contact left, 7 pull-off,
   !> 8 branch end (first and last point of each piece), 9 a*-turn (two case-1 roots
   !> merge: a* turns back, P* does not; not a fold, stability does not change there).
   integer, parameter :: event_none = 0, event_fold = 1, event_switch = 2, &
      event_jump_start = 3, event_jump_end = 4, event_full_contact_reached = 5, &
      event_full_contact_left = 6, event_pull_off = 7, event_branch_end = 8, &
      event_a_turn = 9

   !> What fold_before_switch found: a fold (pushed), or a turn of P* within round-off
   !> of the switch (the corner is the extremum)
   integer, parameter :: turn_pushed = 0, turn_at_switch = 2
   !> Width of the last stretch before a* = 1/2 that approach_half samples
   real(wp), parameter :: end_width = 1.0e-4_wp

contains

   !> Trace the equilibrium branch of `model` for `params` from a* -> 0 to a* = 1/2.
   subroutine trace_branch(model, params, branch, status, errmsg, options)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The traced branch: its points in the order of the curve, with their events
      type(branch_type), intent(out) :: branch
      !> wa_ok; wa_invalid_argument for bad input; wa_not_converged or wa_numerical_error
      !> where the curve leaves what double precision resolves (never a wrong branch)
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> The continuation's controls (trace_options); default: the library's
      type(trace_options), intent(in), optional :: options
      type(trace_options) :: opts

      if (present(options)) opts = options
      call reserve(branch, 256)
      branch%with_gbar = opts%mean_gap
      call check_params(params, status, errmsg)
      if (status /= wa_ok) return
      call check_model(model, status, errmsg)
      if (status /= wa_ok) return
      select case (model)
      case (model_westergaard, model_jkr)
         call closed_form_branch(model, params, opts, branch, status)
      case default
         call cohesive_branch(model, params, opts, branch, status, errmsg)
      end select
   end subroutine trace_branch

   ! ------------------------------------------------------------ closed forms

   !> Westergaard and JKR: P*(a*) sampled uniformly, JKR's folds located by Brent on
   !> dP*/da* = pi sin(2 pi a*) - alpha pi/(2 sqrt(tan) cos^2)   (3.4)
   subroutine closed_form_branch(model, params, opts, branch, status)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(trace_options), intent(in) :: opts
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      integer, parameter :: n = 200
      real(wp) :: a_prev, a, a_end, d_prev, d, a_fold
      integer :: i

      status = wa_ok
      a_end = 0.5_wp
      if (model == model_jkr) a_end = 0.5_wp - 1.0e-9_wp
      a_prev = opts%a_start
      d_prev = closed_slope(model, params, a_prev)
      call append_closed(model, params, a_prev, event_branch_end, 0, branch)
      do i = 1, n
         a = opts%a_start + (a_end - opts%a_start)*real(i, wp)/n
         d = closed_slope(model, params, a)
         if (d*d_prev < 0.0_wp) then
            a_fold = closed_fold(model, params, a_prev, d_prev, a, d)
            call append_closed(model, params, a_fold, event_fold, &
               merge(1, -1, d_prev > 0.0_wp), branch)
         end if
         call append_closed(model, params, a, merge(event_branch_end, event_none, i == n), &
            0, branch)
         a_prev = a; d_prev = d
      end do
   end subroutine closed_form_branch

   pure function closed_slope(model, params, a) result(d)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a
      real(wp) :: d, t, c
      d = pi*sin(2.0_wp*pi*a)
      if (model == model_jkr) then
         t = tan(pi*a)
         c = cos(pi*a)
         d = d - params%alpha*pi/(2.0_wp*sqrt(t)*c*c)
      end if
   end function closed_slope

   pure function closed_fold(model, params, a1, d1, a2, d2) result(a)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a1, d1, a2, d2
      real(wp) :: a
      type(brent_type) :: solver
      logical :: done
      integer :: iter
      call brent_init(solver, a1, d1, a2, d2, 1.0e-15_wp)
      do iter = 1, 200
         call brent_propose(solver, a, done)
         if (done) exit
         call brent_accept(solver, closed_slope(model, params, a))
      end do
      a = solver%b
   end function closed_fold

   subroutine append_closed(model, params, a, event, extremum, branch)
      integer, intent(in) :: model, event, extremum
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a
      type(branch_type), intent(inout) :: branch
      type(state_type) :: s
      integer :: status
      call model_equilibrium(model, params, a, s, status)   ! a* in range: cannot fail
      call append(branch, s, closed_slope(model, params, a) > 0.0_wp .and. extremum == 0, &
         event, extremum)
   end subroutine append_closed

   ! ------------------------------------------------------- cohesive models

   !> The curve from each state at a_start. A piece can return to a* -> 0 (MD: its case-1
   !> sheets join there) while another piece, e.g. case 2, runs to a* = 1/2: the pieces
   !> are traced until one reaches a* = 1/2, each starting and ending with event 8.
   subroutine cohesive_branch(model, params, opts, branch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(trace_options), intent(in) :: opts
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: starts(max_model_roots)
      integer :: n_starts, k

      if (model == model_md .and. params%sigma0 > 0.0_wp) then
         call no_contact_pieces(params, branch, status, errmsg)
         if (status /= wa_ok) return
      end if
      call model_roots(model, params, opts%a_start, starts, n_starts, status, errmsg)
      if (status /= wa_ok) return
      do k = 1, n_starts
         if (visited(branch, starts(k), opts%a_start)) cycle
         call trace_piece(model, params, opts, starts(k), branch, status, errmsg)
         if (status /= wa_ok) return
         if (branch%a_star(branch%n) >= 0.5_wp) return
      end do
      call set_error(wa_numerical_error, "trace_branch: no piece of the curve reaches "// &
         "a* = 1/2", status, errmsg)
   end subroutine cohesive_branch

   !> MD states without contact (zone case 0, a* = 0: a Dugdale zone |x*| < c* around the
   !> crest, P* = -2 Sigma0 c*), as pieces of their own ahead of the contact curve: from the
   !> first interaction (c* = 0, P* = 0) to where the crest gap closes and the family joins
   !> the a* -> 0 end of the contact curve (wa_md_nocontact, md_no_contact_family; a second
   !> piece where the crest gap reopens). P* falls monotonically along them, so under load
   !> control their stability cannot change, and at the first interaction a tensile load
   !> pulls the surfaces into the growing zone: none is stable under load control.
   subroutine no_contact_pieces(params, branch, status, errmsg)
      type(params_type), intent(in) :: params
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, parameter :: n_samples = 41
      type(state_type) :: states(n_samples)
      integer :: piece, n, i
      do piece = 1, 2
         call md_no_contact_family(params, piece, states, n, status, errmsg)
         if (status /= wa_ok) return
         do i = 1, n
            call append(branch, states(i), .false., merge(event_branch_end, event_none, &
               i == 1 .or. i == n), 0)
         end do
      end do
   end subroutine no_contact_pieces

   !> Has a traced piece already started at this start state, or ended on the start line
   !> (a piece returning to a* -> 0 stops at a* <= a_start) in the same zone case and c*?
   !> The zone case matters: near a mechanism change a case-1 root at c* = 1/2 - 1e-7
   !> and the case-2 state sit closer in c* than any tolerance.
   pure logical function visited(branch, s, a_start)
      type(branch_type), intent(in) :: branch
      type(state_type), intent(in) :: s
      real(wp), intent(in) :: a_start
      integer :: i
      visited = .false.
      do i = 1, branch%n
         if (branch%event(i) /= event_branch_end) cycle
         if (branch%zone_case(i) /= s%zone_case) cycle
         if (branch%a_star(i) > a_start*(1.0_wp + 1.0e-3_wp)) cycle
         if (abs(branch%c_star(i) - s%c_star) <= 1.0e-6_wp*s%c_star) visited = .true.
      end do
   end function visited

   !> One piece of the curve from a start state to a* = 1/2 or back to a* -> 0.
   subroutine trace_piece(model, params, opts, start, branch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(trace_options), intent(in) :: opts
      type(state_type), intent(in) :: start
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(curve_point) :: p
      real(wp) :: h
      integer :: n0
      logical :: sampled, handled

      n0 = branch%n
      p%a = start%a_star
      p%zone_case = start%zone_case
      p%y = curve_y_max
      p%t = [1.0_wp, 0.0_wp]
      p%dp = case2_slope(p%a)
      if (p%zone_case == zone_inside) then
         p%y = curve_variable(model, start)
         if (curve_weight(model)*(curve_y_max - p%y) <= 1.0e-12_wp) then
            ! c* = 1/2 within rounding (the case-1 root is being born at a_start): the
            ! tangent is undefined there; start on case 2, whose step finds where case 1
            ! takes over
            p%zone_case = zone_whole_period
            p%y = curve_y_max
         else
            call orient(model, params, p, [1.0_wp, 0.0_wp])
         end if
      end if
      call push(model, params, p, event_branch_end, 0, branch)
      h = opts%step_max
      sampled = .false.
      do while (branch%n - n0 < opts%max_points)
         if (p%zone_case == zone_inside .and. .not. sampled .and. p%t(1) > 0.0_wp .and. &
            p%a >= 0.5_wp - end_width) then
            sampled = .true.
            call approach_half(model, params, p, branch, handled, status, errmsg)
            if (status /= wa_ok) return
            if (branch%event(branch%n) == event_branch_end) return
            if (handled) cycle
         end if
         if (p%zone_case == zone_inside) then
            call step_case1(model, params, opts, p, h, branch, status, errmsg)
         else
            call step_case2(model, params, opts, p, h, branch, status, errmsg)
         end if
         if (status /= wa_ok) return
         if (branch%event(branch%n) == event_branch_end) return
      end do
      call set_error(wa_not_converged, "trace_branch: max_points reached before a* = 1/2", &
         status, errmsg)
   end subroutine trace_piece

   !> One step along case 2 (explicit in a*): stop at the end, or locate where the
   !> case-1 root enters (F(a*, y_max) changes sign to >= 0) and switch.
   subroutine step_case2(model, params, opts, p, h, branch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(trace_options), intent(in) :: opts
      type(curve_point), intent(inout) :: p
      real(wp), intent(inout) :: h
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: a_new, dir, v_new, v_old, slope_before
      type(curve_point) :: q

      status = wa_ok
      dir = sign(1.0_wp, p%t(1))
      if (p%t(1) == 0.0_wp) dir = 1.0_wp
      a_new = min(0.5_wp, max(opts%a_start, p%a + dir*opts%step_max))
      v_new = -1.0_wp
      if (a_new < 0.5_wp) v_new = curve_residual(model, params, a_new, curve_y_max)
      if (v_new < 0.0_wp) then
         q = case2_point(model, a_new, dir)
         if (a_new >= 0.5_wp .or. a_new <= opts%a_start) then
            q%zone_case = merge(zone_full_contact, zone_whole_period, a_new >= 0.5_wp)
            call push(model, params, q, event_branch_end, 0, branch)
         else
            call push(model, params, q, event_none, 0, branch)
         end if
         p = q
         return
      end if
      v_old = curve_residual(model, params, p%a, curve_y_max)
      q%a = switch_abscissa(model, params, p%a, v_old, a_new, v_new, status, errmsg)
      if (status /= wa_ok) return
      q%y = curve_y_max
      q%zone_case = zone_inside
      slope_before = dir*case2_slope(q%a)
      call orient(model, params, q, [0.0_wp, -1.0_wp])     ! into c* < 1/2
      call push(model, params, q, event_switch, corner_extremum(slope_before, q%dp), branch)
      p = q
      h = max(opts%step_min, 0.1_wp*opts%step_max)
   end subroutine step_case2

   !> One pseudo-arclength step on the case-1 curve, with fold location and the switch
   !> to case 2 where the step would carry y past y_max.
   subroutine step_case1(model, params, opts, p, h, branch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(trace_options), intent(in) :: opts
      type(curve_point), intent(inout) :: p
      real(wp), intent(inout) :: h
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(curve_point) :: q, f
      integer :: iters
      logical :: ok

      status = wa_ok
      do
         call corrector(model, params, p, h, q, iters, ok)
         if (ok) ok = q%a > 0.0_wp .and. q%a < 0.5_wp .and. q%y <= curve_y_max
         if (ok) then
            call orient(model, params, q, p%t)
            ok = dot_product(p%t, q%t) >= cos(opts%max_turn)
         end if
         if (ok) exit
         if (crosses_case2(model, params, p, h)) then
            call switch_to_case2(model, params, p, h, branch, status, errmsg)
            return
         end if
         h = 0.5_wp*h
         if (h < opts%step_min) then
            call set_error(wa_not_converged, "trace_branch: step size underflow on the "// &
               "case-1 curve", status, errmsg)
            return
         end if
      end do
      if (p%dp*q%dp < 0.0_wp) then                  ! a fold of P*
         call locate_zero(model, params, p, h, 1, f, status, errmsg)
         if (status /= wa_ok) return
         call push(model, params, f, event_fold, merge(1, -1, p%dp > 0.0_wp), branch)
      else if (p%t(1)*q%t(1) < 0.0_wp) then         ! a* turns back: stability flips
         call locate_zero(model, params, p, h, 2, f, status, errmsg)
         if (status /= wa_ok) return
         call push(model, params, f, event_a_turn, 2, branch)
      end if
      if (q%a <= opts%a_start .or. q%a >= 0.5_wp - 1.0e-12_wp) then
         call push(model, params, q, event_branch_end, 0, branch)
      else
         call push(model, params, q, event_none, 0, branch)
      end if
      p = q
      if (iters <= 3) h = min(opts%step_max, 1.5_wp*h)
      if (iters >= 5) h = 0.5_wp*h
   end subroutine step_case1

   !> The last stretch to a* = 1/2 (1/2 - a* < end_width, travelling towards 1/2). a* holds
   !> 1/2 - a* only to 5.5e-17 absolute, so near 1/2 the corrector's finite differences
   !> fail (large mu: the zone reaches c* = 1/2 within 1e-8 of a* = 1/2) and its steps
   !> crowd there. The curve is sampled instead by point solves at 1/2 - a* = b0 r^k,
   !> following the state nearest the previous c*, and the switch to case 2 is located by
   !> Brent on F(a*, y_max). Anything else (a failed solve, a jump of the zone variable,
   !> P* turning, a switch not bracketed) hands the last sample back to the continuation
   !> (handled = .false.).
   subroutine approach_half(model, params, p, branch, handled, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(inout) :: p
      type(branch_type), intent(inout) :: branch
      logical, intent(out) :: handled
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), parameter :: ratio = 0.5_wp, b_last = 1.0e-15_wp, max_y_jump = 2.0_wp
      type(state_type) :: s, s_prev
      type(curve_point) :: q
      real(wp) :: b, a, slope, v_prev, v_here, a_switch
      integer :: k, st

      handled = .false.
      status = wa_ok
      s_prev = curve_state(model, params, p%a, p%y)
      b = 0.5_wp - p%a
      do k = 1, 200
         b = max(ratio*b, 0.999_wp*b_last)
         a = 0.5_wp - b
         call curve_equilibrium(model, params, a, s_prev%c_star, s, st)
         if (st /= wa_ok) exit
         if (s%zone_case == zone_whole_period) then            ! c* reached 1/2 on the way
            v_prev = curve_residual(model, params, p%a, curve_y_max)
            v_here = curve_residual(model, params, a, curve_y_max)
            if (v_prev*v_here > 0.0_wp) exit
            a_switch = switch_abscissa(model, params, p%a, v_prev, a, v_here, st)
            if (st /= wa_ok) exit
            slope = (curve_case2_load(model, params, a_switch) - s_prev%p_star) &
               /(a_switch - p%a)
            q = case2_point(model, a_switch, 1.0_wp)
            call push(model, params, q, event_switch, corner_extremum(slope, q%dp), branch)
            p = q
            handled = .true.
            return
         end if
         if (s%zone_case /= zone_inside) exit
         q%a = a
         q%y = curve_variable(model, s)
         q%zone_case = zone_inside
         q%t = [1.0_wp, 0.0_wp]
         slope = (s%p_star - s_prev%p_star)/(a - p%a)
         if (abs(q%y - p%y) > max_y_jump .or. slope*p%dp <= 0.0_wp) exit
         q%dp = slope
         q%det = p%det                 ! no extremum of P* since p: stability carries over
         if (b <= b_last) then        ! still case 1: the switch is beyond double precision
            call set_error(wa_numerical_error, "trace_branch: the interaction zone "// &
               "reaches c* = 1/2 closer than 1e-15 to a* = 1/2, which double precision "// &
               "does not resolve: mu is too large for this alpha (the JKR limit applies)", &
               status, errmsg)
            return
         end if
         call push(model, params, q, event_none, 0, branch)
         p = q
         s_prev = s
      end do
      call orient(model, params, p, [1.0_wp, 0.0_wp])       ! back to the continuation
   end subroutine approach_half

   !> Locate where the case-1 curve reaches y_max, push the switch event, go on in case 2.
   subroutine switch_to_case2(model, params, p, h, branch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(inout) :: p
      real(wp), intent(inout) :: h
      type(branch_type), intent(inout) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: a_next, v_here, v_next, dir, slope_before
      type(curve_point) :: q
      integer :: turn_at

      a_next = min(0.5_wp - 1.0e-15_wp, max(1.0e-300_wp, p%a + 2.0_wp*h*p%t(1)))
      v_here = curve_residual(model, params, p%a, curve_y_max)
      v_next = curve_residual(model, params, a_next, curve_y_max)
      ! case 2 goes on to the side where it holds (F(a*, y_max) < 0): ahead for DW; for
      ! MD it may lie behind, where the curve came from along its second case-1 root
      dir = sign(1.0_wp, p%t(1))
      if (v_here < 0.0_wp) dir = -dir
      q%a = switch_abscissa(model, params, p%a, v_here, a_next, v_next, status, errmsg)
      if (status /= wa_ok) return
      q%y = curve_y_max
      q%zone_case = zone_inside
      call orient(model, params, q, p%t)
      slope_before = q%dp
      ! P* turned between the last point and the switch, where the curve runs steeply up
      ! to c* = 1/2 and the corrector cannot follow: locate that fold by the point solver
      if (p%dp*slope_before < 0.0_wp) then
         call fold_before_switch(model, params, p, q%a, status, errmsg, branch, turn_at)
         if (status /= wa_ok) return
         ! a turn within round-off of the switch is no fold: the corner is the extremum,
         ! with P* arriving as it did before the turn
         if (turn_at == turn_at_switch) slope_before = p%dp
      else if (p%dp*(curve_case2_load(model, params, q%a) - branch%p_star(branch%n)) < 0.0_wp &
         .and. branch%n > 0) then
         ! P* leaves p and arrives at the switch in the same direction, yet ends on the
         ! other side of p's load: the slopes are not to be trusted there, the samples are
         call folds_before_switch(model, params, p, q%a, slope_before, status, errmsg, branch)
         if (status /= wa_ok) return
      end if
      q = case2_point(model, q%a, dir)
      call push(model, params, q, event_switch, corner_extremum(slope_before, q%dp), branch)
      p = q
   end subroutine switch_to_case2

   !> The extremum of P* on the case-1 curve between p and the switch at a_switch, by
   !> golden sections on P*(a*) of the state nearest p's c* (to 1e-12 relative in a*),
   !> pushed as a fold.
   subroutine fold_before_switch(model, params, p, a_switch, status, errmsg, branch, turn_at)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: a_switch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type), intent(inout) :: branch
      !> Either turn_pushed (the fold is pushed, or none is found) or turn_at_switch (P*
      !> turns within round-off of the switch: no fold is pushed)
      integer, intent(out) :: turn_at
      type(state_type) :: s, s_hint
      type(curve_point) :: f
      real(wp) :: sgn, p_switch

      turn_at = turn_pushed
      s_hint = curve_state(model, params, p%a, p%y)
      sgn = sign(1.0_wp, p%dp)                 ! +1: a maximum of P*, -1: a minimum
      call case1_extremum(model, params, s_hint%c_star, p%a, a_switch, sgn, s, status, errmsg)
      if (status /= wa_ok) return
      ! a turn of P* within round-off of the switch's load, beyond p's (or of both) is no
      ! fold: the corner is the extremum. (One within round-off of p's load only is a
      ! fold: P* then moves on to the switch by more than round-off.)
      p_switch = curve_case2_load(model, params, a_switch)
      if (sgn*(s%p_star - max(sgn*s_hint%p_star, sgn*p_switch)*sgn) <= &
         1.0e-12_wp*max(1.0_wp, abs(s%p_star)) .and. sgn*p_switch >= sgn*s_hint%p_star - &
         1.0e-12_wp*max(1.0_wp, abs(s%p_star))) then
         turn_at = turn_at_switch
         return
      end if
      f%a = s%a_star
      f%y = curve_variable(model, s)
      f%zone_case = zone_inside
      f%t = p%t
      call push(model, params, f, event_fold, nint(sgn), branch)
   end subroutine fold_before_switch

   !> The folds of P* on the case-1 curve between p and the switch at a_switch where the
   !> slopes at the two ends contradict the loads (P* leaves p rising, yet reaches the
   !> switch below p's load, or the reverse): the curve runs steeply up to c* = 1/2 there
   !> and the slope at the switch is unreliable. P* is sampled at 32 points by the point
   !> solver; every turn of the samples is refined by golden sections and pushed as a
   !> fold, in order; slope_in is the sign with which P* arrives at the switch.
   subroutine folds_before_switch(model, params, p, a_switch, slope_in, status, errmsg, &
         branch)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: a_switch
      real(wp), intent(inout) :: slope_in
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type), intent(inout) :: branch
      integer, parameter :: n = 32
      type(state_type) :: s_hint, s
      type(curve_point) :: f
      real(wp) :: a(0:n), load(0:n), d(0:n), sgn, noise
      integer :: k

      status = wa_ok
      s_hint = curve_state(model, params, p%a, p%y)
      do k = 0, n
         a(k) = p%a + (a_switch - p%a)*real(k, wp)/real(n, wp)
      end do
      load(0) = s_hint%p_star
      load(n) = curve_case2_load(model, params, a_switch)
      do k = 1, n - 1
         load(k) = load_at(a(k))
         if (status /= wa_ok) return
      end do
      ! differences below the rounding of P* carry no sign
      noise = 64.0_wp*epsilon(1.0_wp)*maxval(abs(load))
      ! d(0): the slope P* leaves p with (a turn before the first sample shows there)
      d(0) = sign(tiny(1.0_wp), p%dp)
      d(1:n) = load(1:n) - load(0:n - 1)
      where (abs(d(1:n)) <= noise) d(1:n) = 0.0_wp
      do k = 1, n
         if (d(k) == 0.0_wp) d(k) = d(k - 1)
      end do
      slope_in = sign(1.0_wp, d(n))
      do k = 0, n - 1
         if (.not. (d(k)*d(k + 1) < 0.0_wp)) cycle
         sgn = sign(1.0_wp, d(k))             ! +1: a maximum at sample k, -1: a minimum
         call case1_extremum(model, params, s_hint%c_star, a(max(k - 1, 0)), a(k + 1), sgn, &
            s, status, errmsg)
         if (status /= wa_ok) return
         f%a = s%a_star
         f%y = curve_variable(model, s)
         f%zone_case = zone_inside
         f%t = p%t
         call push(model, params, f, event_fold, nint(sgn), branch)
      end do
   contains
      real(wp) function load_at(x)
         real(wp), intent(in) :: x
         type(state_type) :: st
         call curve_equilibrium(model, params, x, s_hint%c_star, st, status, errmsg)
         load_at = st%p_star
      end function load_at
   end subroutine folds_before_switch

   ! ------------------------------------------------------------ a point stored

   !> Store q (a case-1 point by its curve state, a case-2 point by the explicit load) with
   !> its mean gap (unless the branch goes without) and its stability.
   subroutine push(model, params, q, event, extremum, branch)
      integer, intent(in) :: model, event, extremum
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: q
      type(branch_type), intent(inout) :: branch
      type(state_type) :: s
      logical :: stable
      integer :: status
      real(wp) :: g
      if (q%zone_case == zone_inside) then
         s = curve_state(model, params, q%a, q%y)
      else
         s%a_star = q%a
         s%c_star = 0.5_wp
         s%gap_width = 0.5_wp - q%a
         s%p_star = curve_case2_load(model, params, q%a)
         s%zone_case = q%zone_case
      end if
      ! the curve's states leave gbar to the accepted points (MD: a quadrature)
      if (branch%with_gbar) then
         ! a solved state: DW and MD take their mean gap without re-checking it
         if (model == model_dw) then
            s%gbar = dw_state_gbar(params, s)
         else if (model == model_md) then
            s%gbar = md_state_gbar(params, s)
         else
            call state_mean_gap(model, params, s, g, status)
            s%gbar = g
         end if
      else
         s%gbar = ieee_value(1.0_wp, ieee_quiet_nan)
      end if
      if (q%zone_case == zone_inside) then
         stable = q%det > 0.0_wp
      else                                             ! one degree of freedom: dP*/da* > 0
         stable = q%dp*sign(1.0_wp, q%t(1)) > 0.0_wp .and. q%t(1) /= 0.0_wp
      end if
      call append(branch, s, stable .and. abs(extremum) /= 1, event, extremum)
   end subroutine push

end module wa_branch
