!> Pseudo-arclength continuation of the equilibrium curve P*(a*), c*(a*) of the cohesive
!> models over 0 < a* < 1/2, through every fold, with the zone-case switches (c* reaching
!> 1/2 and leaving it) and the folds of P* (dP*/da* = 0) located as events.
!>
!> The case-1 curve is the zero set of one residual F(a*, y) (y: the model's zone
!> variable, wa_curve); it is followed in the plane z = (a*, w y) with a tangent
!> predictor and a Newton corrector on the arclength-augmented system
!>   F(z) = 0,  t . (z - z_pred) = 0,
!> with steps adapted to the corrector's convergence and to the turn of the tangent.
!> Case 2 (c* = 1/2) is explicit in a*; it holds where F(a*, y_max) < 0.
module wa_branch
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_not_converged, wa_numerical_error, &
      set_error
   use wa_params, only: params_type, check_params
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact, &
      model_westergaard, model_jkr, model_dw, model_md
   use wa_curve, only: curve_residual, curve_state, curve_values, curve_y_max, curve_weight, &
      curve_case2_load, curve_variable, curve_equilibrium, curve_load
   use wa_models, only: check_model, model_roots, model_equilibrium, max_model_roots
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_separation, only: state_mean_gap, md_no_contact_family, dw_state_gbar, md_state_gbar
   implicit none
   private

   public :: branch_type, trace_options, trace_branch
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

   !> A traced branch: points in the order of the curve (not necessarily of a*).
   type :: branch_type
      integer :: n = 0
      real(wp), allocatable :: a_star(:), c_star(:), p_star(:)
      !> Mean gap over Delta, gbar* (doc/theory.md, "Separation")
      real(wp), allocatable :: gbar(:)
      integer, allocatable :: zone_case(:)
      !> Stable under load control (doc/theory.md, "Stability"): case 2 where dP*/da* > 0;
      !> case 1 where D = dP*/da* dF/dy - dP*/dy dF/da* > 0, which changes sign only at
      !> extrema of P* along the curve, never where a* alone turns. False at extrema.
      logical, allocatable :: stable(:)
      !> event code of the point (0 for ordinary points)
      integer, allocatable :: event(:)
      !> +1 local maximum of P* along the curve, -1 local minimum (folds and corners),
      !> 2 where a* turns back (two case-1 roots merge; stability changes), else 0
      integer, allocatable :: extremum(:)
      !> gbar holds the mean gaps (trace_options%mean_gap); else it is NaN throughout
      logical :: with_gbar = .true.
   end type branch_type

   !> Continuation controls (defaults suit every model and parameter tested).
   type :: trace_options
      !> Largest and smallest step, in units of a* along the scaled arclength.
      real(wp) :: step_max = 0.004_wp, step_min = 1.0e-11_wp
      !> The branch starts at a* = a_start (the limit a* -> 0)
      real(wp) :: a_start = 1.0e-6_wp
      !> Largest turn of the tangent per step [rad]
      real(wp) :: max_turn = 0.15_wp
      integer :: max_points = 20000
      !> Compute gbar* at every point (.false.: NaN; for callers that need only P*, such
      !> as the load-control mechanisms of the adhesion map)
      logical :: mean_gap = .true.
   end type trace_options

   !> A point of the curve in the scaled plane, with its derivatives.
   type :: curve_point
      real(wp) :: a = 0.0_wp, y = 0.0_wp
      integer :: zone_case = zone_inside
      !> unit tangent (da, w dy) in the direction of travel
      real(wp) :: t(2) = 0.0_wp
      !> dP*/dsigma along the direction of travel
      real(wp) :: dp = 0.0_wp
      !> D = P_a F_y - P_y F_a (case 1): > 0 where the state is stable under load control
      real(wp) :: det = 0.0_wp
   end type curve_point

   integer, parameter :: max_newton = 12
   !> |F| at which the corrector's point is on the curve to rounding (F is a logarithm of
   !> O(1) ratios: its own rounding is a few epsilon)
   real(wp), parameter :: f_floor = 4.0_wp*epsilon(1.0_wp)
   !> What fold_before_switch found: a fold (pushed), or a turn of P* within round-off
   !> of the switch (the corner is the extremum)
   integer, parameter :: turn_pushed = 0, turn_at_switch = 2
   !> Width of the last stretch before a* = 1/2 that approach_half samples
   real(wp), parameter :: end_width = 1.0e-4_wp

contains

   !> Trace the equilibrium branch of `model` for `params` from a* -> 0 to a* = 1/2.
   subroutine trace_branch(model, params, branch, status, errmsg, options)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(out) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
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
   !> the a* -> 0 end of the contact curve (wa_separation, md_no_contact_family; a second
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

   !> Predictor z + h t, then Newton on F = 0, t.(z - z_pred) = 0.
   pure subroutine corrector(model, params, p, h, q, iters, ok)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: h
      type(curve_point), intent(out) :: q
      integer, intent(out) :: iters
      logical, intent(out) :: ok
      real(wp) :: w, z(2), zp(2), g(2), f, r2, det, dz(2)

      w = curve_weight(model)
      zp = [p%a, w*p%y] + h*p%t
      z = zp
      ok = .false.
      do iters = 1, max_newton
         if (z(1) <= 0.0_wp .or. z(1) >= 0.5_wp .or. z(2)/w > curve_y_max) return
         call residual_gradient(model, params, z(1), z(2)/w, f, g)
         g(2) = g(2)/w
         if (.not. (ieee_is_finite(f) .and. all(ieee_is_finite(g)))) return
         r2 = dot_product(p%t, z - zp)
         det = g(1)*p%t(2) - g(2)*p%t(1)
         if (det == 0.0_wp) return
         dz = [(-f*p%t(2) + r2*g(2))/det, (-g(1)*r2 + p%t(1)*f)/det]
         z = z + dz
         ! converged; or F at its rounding floor where the gradient is small (MD near a
         ! reconnection of the case-1 curve: |grad F| ~ 1e-2), which keeps the steps at
         ! ~1e-14 however small h is
         if (norm2(dz) <= 1.0e-14_wp*max(1.0_wp, norm2(z)) .or. (abs(f) <= f_floor .and. &
            norm2(dz) <= 1.0e-12_wp*max(1.0_wp, norm2(z)))) then
            ok = .true.
            exit
         end if
      end do
      if (ok) call polish(model, params, z(1), z(2), w, g(2)*w)
      q%a = z(1)
      q%y = z(2)/w
      q%zone_case = zone_inside
   end subroutine corrector

   !> Newton steps in y at fixed a*: the corrector's step test acts on w y, which
   !> leaves y (and a steep P*(y) near a* -> 1/2) short of full precision.
   pure subroutine polish(model, params, a, wy, w, f_y)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, w, f_y
      real(wp), intent(inout) :: wy
      real(wp) :: f, dy, slope, h
      integer :: k
      slope = f_y
      do k = 1, 3
         f = curve_residual(model, params, a, wy/w)
         if (.not. ieee_is_finite(f) .or. slope == 0.0_wp) return
         if (k == 1) then                  ! a local slope: F may be steep on a small scale
            h = -1.0e-9_wp*max(1.0_wp, abs(wy/w))
            slope = (curve_residual(model, params, a, wy/w + h) - f)/h
            if (slope == 0.0_wp .or. .not. ieee_is_finite(slope)) slope = f_y
         end if
         dy = -f/slope
         if (abs(dy) > 1.0e-6_wp*max(1.0_wp, abs(wy/w)) .or. &
            wy/w + dy > curve_y_max) return
         wy = wy + w*dy
      end do
   end subroutine polish

   !> F and its forward-difference gradient (enough for Newton's direction).
   pure subroutine residual_gradient(model, params, a, y, f, g)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, y
      real(wp), intent(out) :: f, g(2)
      real(wp) :: ha, hy
      f = curve_residual(model, params, a, y)
      ! F varies on the scale of the distance to the nearer end of 0 < a* < 1/2
      ha = 1.0e-7_wp*min(max(a, 1.0e-3_wp), 0.5_wp - a)
      if (a + ha >= 0.5_wp) ha = -ha
      hy = -1.0e-7_wp*max(abs(y), 1.0_wp)
      g(1) = (curve_residual(model, params, a + ha, y) - f)/ha
      g(2) = (curve_residual(model, params, a, y + hy) - f)/hy
   end subroutine residual_gradient

   !> Unit tangent of the case-1 curve at q, oriented along `previous`, and dP*/dsigma.
   pure subroutine orient(model, params, q, previous)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(inout) :: q
      real(wp), intent(in) :: previous(2)
      real(wp) :: fa, fy, pa, py, w
      w = curve_weight(model)
      call accurate_partials(model, params, q%a, q%y, fa, fy, pa, py)
      q%t = [fy/w, -fa]
      q%t = q%t/norm2(q%t)
      if (dot_product(q%t, previous) < 0.0_wp) q%t = -q%t
      q%dp = pa*q%t(1) + py*(q%t(2)/w)
      q%det = pa*fy - py*fa
   end subroutine orient

   !> Five-point differences of F and P* in a* and y (one-sided where the domain ends):
   !> error ~ h^4, accurate to ~1e-12, which places folds to ~1e-11 in a*.
   pure subroutine accurate_partials(model, params, a, y, fa, fy, pa, py)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, y
      real(wp), intent(out) :: fa, fy, pa, py
      real(wp) :: ha, hy, fv(0:4), pv(0:4)
      integer :: k

      ha = 2.0e-3_wp*min(a, 0.5_wp - a, 0.05_wp)
      do k = 0, 4
         call values_at(a + (k - 2)*ha, y, fv(k), pv(k))
      end do
      fa = central5(fv, ha)
      pa = central5(pv, ha)
      ! in y the functions vary on the scale of the distance to y_max (c* = 1/2): a
      ! central stencil well inside it (its centre is the a* stencil's), a one-sided one
      ! below y_max on the boundary
      hy = min(2.0e-3_wp*max(1.0_wp, abs(y)), 0.02_wp*(curve_y_max - y))
      if (hy > 0.0_wp) then
         do k = 0, 4
            if (k /= 2) call values_at(a, y + (k - 2)*hy, fv(k), pv(k))
         end do
         fy = central5(fv, hy)
         py = central5(pv, hy)
      else
         hy = 2.0e-3_wp
         do k = 0, 4
            call values_at(a, y - k*hy, fv(k), pv(k))
         end do
         fy = -onesided5(fv, hy)
         py = -onesided5(pv, hy)
      end if
   contains
      pure subroutine values_at(aa, yy, fval, pval)
         real(wp), intent(in) :: aa, yy
         real(wp), intent(out) :: fval, pval
         call curve_values(model, params, aa, yy, fval, pval)
      end subroutine values_at
   end subroutine accurate_partials

   pure real(wp) function central5(v, h)
      real(wp), intent(in) :: v(0:4), h
      central5 = (v(0) - 8.0_wp*v(1) + 8.0_wp*v(3) - v(4))/(12.0_wp*h)
   end function central5

   pure real(wp) function onesided5(v, h)
      real(wp), intent(in) :: v(0:4), h
      onesided5 = (-25.0_wp*v(0) + 48.0_wp*v(1) - 36.0_wp*v(2) + 16.0_wp*v(3) - 3.0_wp*v(4)) &
         /(12.0_wp*h)
   end function onesided5

   !> Brent over the arclength between p and the accepted step h for the zero of
   !> dP*/dsigma (which = 1, a fold) or of da*/dsigma (which = 2, a* turns back).
   subroutine locate_zero(model, params, p, h, which, f, status, errmsg)
      integer, intent(in) :: model, which
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: h
      type(curve_point), intent(out) :: f
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: sigma
      logical :: done, ok
      integer :: iter, iters

      status = wa_ok
      call corrector(model, params, p, h, f, iters, ok)
      call orient(model, params, f, p%t)
      call brent_init(solver, 0.0_wp, monitored(p), h, monitored(f), 1.0e-13_wp)
      do iter = 1, 100
         call brent_propose(solver, sigma, done)
         if (done) exit
         call corrector(model, params, p, sigma, f, iters, ok)
         if (.not. ok) exit
         call orient(model, params, f, p%t)
         call brent_accept(solver, monitored(f))
      end do
      call corrector(model, params, p, solver%b, f, iters, ok)
      if (.not. (done .and. ok)) then
         call set_error(wa_not_converged, "trace_branch: a fold could not be located", &
            status, errmsg)
         return
      end if
      call orient(model, params, f, p%t)
   contains
      pure real(wp) function monitored(q)
         type(curve_point), intent(in) :: q
         monitored = merge(q%dp, q%t(1), which == 1)
      end function monitored
   end subroutine locate_zero

   !> Does the curve leave case 1 (reach y_max) within the next step?
   logical function crosses_case2(model, params, p, h)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: h
      real(wp) :: a_next
      a_next = min(0.5_wp - 1.0e-15_wp, max(1.0e-300_wp, p%a + 2.0_wp*h*p%t(1)))
      ! F(a*, y_max) changes sign across the a* where the curve reaches y_max; but it also
      ! changes where another sheet is born at y_max (MD: a second case-1 root and case 2
      ! appear together), so the curve itself must be heading into y_max within the step
      crosses_case2 = p%t(2) > 0.0_wp .and. &
         curve_weight(model)*(curve_y_max - p%y) <= h*p%t(2)
      if (crosses_case2) crosses_case2 = &
         curve_residual(model, params, a_next, curve_y_max) &
         *curve_residual(model, params, p%a, curve_y_max) <= 0.0_wp
   end function crosses_case2

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
      !> turn_pushed: the fold is pushed (or none found); turn_at_switch: P* turns within
      !> round-off of the switch, no fold is pushed
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

   !> The extremum of P* (a maximum for sgn = +1) on the case-1 curve between a* = a1 and
   !> a2: golden sections on P*(a*) of the state nearest c_hint, to 1e-12 relative in a*.
   subroutine case1_extremum(model, params, c_hint, a1, a2, sgn, s, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: c_hint, a1, a2, sgn
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), parameter :: golden = 0.3819660112501051518_wp
      real(wp) :: lo, hi, x1, x2, f1, f2
      integer :: iter
      status = wa_ok
      lo = min(a1, a2); hi = max(a1, a2)
      x1 = lo + golden*(hi - lo); x2 = hi - golden*(hi - lo)
      f1 = sgn*load_at(x1); f2 = sgn*load_at(x2)
      do iter = 1, 200
         if (status /= wa_ok .or. hi - lo <= 1.0e-12_wp*hi) exit
         if (f1 > f2) then
            hi = x2; x2 = x1; f2 = f1
            x1 = lo + golden*(hi - lo); f1 = sgn*load_at(x1)
         else
            lo = x1; x1 = x2; f1 = f2
            x2 = hi - golden*(hi - lo); f2 = sgn*load_at(x2)
         end if
      end do
      if (status /= wa_ok) return
      call curve_equilibrium(model, params, 0.5_wp*(lo + hi), c_hint, s, status, errmsg)
      if (status /= wa_ok) return
      if (s%zone_case /= zone_inside) call set_error(wa_numerical_error, "trace_branch: "// &
         "a fold before a case switch could not be located", status, errmsg)
   contains
      real(wp) function load_at(a)
         real(wp), intent(in) :: a
         type(state_type) :: st
         call curve_equilibrium(model, params, a, c_hint, st, status, errmsg)
         load_at = st%p_star
      end function load_at
   end subroutine case1_extremum

   !> The a* where F(a*, y_max) = 0 between a1 and a2 (case switch, to ~1e-15).
   function switch_abscissa(model, params, a1, v1, a2, v2, status, errmsg) result(a)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a1, v1, a2, v2
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: a
      type(brent_type) :: solver
      logical :: done
      integer :: iter
      status = wa_ok
      if (v1*v2 > 0.0_wp) then
         a = a1
         call set_error(wa_numerical_error, "trace_branch: case switch not bracketed", &
            status, errmsg)
         return
      end if
      call brent_init(solver, a1, v1, a2, v2, 1.0e-16_wp)
      do iter = 1, 200
         call brent_propose(solver, a, done)
         if (done) exit
         call brent_accept(solver, curve_residual(model, params, a, curve_y_max))
      end do
      a = solver%b
   end function switch_abscissa

   !> A case-2 point at a*, travelling in direction dir of a*; P* = A^2 - const.
   pure function case2_point(model, a, dir) result(q)
      integer, intent(in) :: model
      real(wp), intent(in) :: a, dir
      type(curve_point) :: q
      q%a = a
      q%y = curve_y_max
      q%zone_case = zone_whole_period
      q%t = [dir, 0.0_wp]
      q%dp = dir*case2_slope(a)
   end function case2_point

   !> dP*/da* in case 2: d(A^2)/da* = pi sin(2 pi a*)   (2.28a)
   pure real(wp) function case2_slope(a)
      real(wp), intent(in) :: a
      case2_slope = pi*sin(2.0_wp*pi*a)
   end function case2_slope

   !> Extremum at a corner: +1 if P* rose into it and falls after, -1 the reverse.
   pure integer function corner_extremum(before, after)
      real(wp), intent(in) :: before, after
      corner_extremum = 0
      if (before > 0.0_wp .and. after < 0.0_wp) corner_extremum = 1
      if (before < 0.0_wp .and. after > 0.0_wp) corner_extremum = -1
   end function corner_extremum

   ! ------------------------------------------------------------ storage

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

   subroutine append(branch, s, stable, event, extremum)
      type(branch_type), intent(inout) :: branch
      type(state_type), intent(in) :: s
      logical, intent(in) :: stable
      integer, intent(in) :: event, extremum
      if (branch%n == size(branch%a_star)) call reserve(branch, 2*branch%n)
      branch%n = branch%n + 1
      branch%a_star(branch%n) = s%a_star
      branch%c_star(branch%n) = s%c_star
      branch%p_star(branch%n) = s%p_star
      branch%gbar(branch%n) = s%gbar
      branch%zone_case(branch%n) = s%zone_case
      branch%stable(branch%n) = stable
      branch%event(branch%n) = event
      branch%extremum(branch%n) = extremum
   end subroutine append

   subroutine reserve(branch, capacity)
      type(branch_type), intent(inout) :: branch
      integer, intent(in) :: capacity
      if (.not. allocated(branch%a_star)) branch%n = 0
      call grow_real(branch%a_star, branch%n, capacity)
      call grow_real(branch%c_star, branch%n, capacity)
      call grow_real(branch%p_star, branch%n, capacity)
      call grow_real(branch%gbar, branch%n, capacity)
      call grow_int(branch%zone_case, branch%n, capacity)
      call grow_int(branch%event, branch%n, capacity)
      call grow_int(branch%extremum, branch%n, capacity)
      call grow_logical(branch%stable, branch%n, capacity)
   end subroutine reserve

   pure subroutine grow_real(x, n, capacity)
      real(wp), allocatable, intent(inout) :: x(:)
      integer, intent(in) :: n, capacity
      real(wp), allocatable :: tmp(:)
      allocate (tmp(capacity))
      if (n > 0) tmp(1:n) = x(1:n)
      call move_alloc(tmp, x)
   end subroutine grow_real

   pure subroutine grow_int(x, n, capacity)
      integer, allocatable, intent(inout) :: x(:)
      integer, intent(in) :: n, capacity
      integer, allocatable :: tmp(:)
      allocate (tmp(capacity))
      if (n > 0) tmp(1:n) = x(1:n)
      call move_alloc(tmp, x)
   end subroutine grow_int

   pure subroutine grow_logical(x, n, capacity)
      logical, allocatable, intent(inout) :: x(:)
      integer, intent(in) :: n, capacity
      logical, allocatable :: tmp(:)
      allocate (tmp(capacity))
      if (n > 0) tmp(1:n) = x(1:n)
      call move_alloc(tmp, x)
   end subroutine grow_logical

end module wa_branch
