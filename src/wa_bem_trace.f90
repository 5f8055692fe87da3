!> Pseudo-arclength continuation of the smooth-adhesion equilibrium curve in
!> z = (gap field, P*), from far apart (P* ~ 0, large gbar*) through every fold to full
!> contact (the whole period inside the repulsive part of the law, h <= eps, stable under
!> both controls, compressive and rising), with the stability of every point under both
!> controls and the events located on the curve (doc/theory.md, "Smooth adhesion").
!>
!> Step control: a step is refused (and halved) when its corrector fails, when the
!> tangent turns by more than max_turn (in the arclength metric) or when the load or
!> the mean gap changes by more than dp_max, dg_max times the problem's scales of load
!> and gap, max(1, half the law's peak tension) and max(1, the law's range) (so the
!> trace's point count does not grow with them); the new tangent is oriented along
!> the old one, so the trace cannot turn back on itself at a sharp fold.
!>
!> Inertia: from the factorisation at each event point and after it (dense
!> preconditioner); with the two-grid one it is counted across the folds instead: at a
!> simple fold the Hessian's eigenvalue through zero has the eigenvector t_h and moves
!> with d lambda/ds = sum(w sigma''(h) t_h^3)/|t_h|^2, so the count of its control
!> changes by -sign of that sum (doc/theory.md, "Smooth adhesion").
module wa_bem_trace
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, wa_not_converged, wa_capacity_too_small, &
      set_error
   use wa_bem_law, only: law_zero, law_peak, law_curvature, law_eval
   use wa_bem_solver, only: lj_problem_type, jacobian_type, point_info_type, factor_at, &
      bordered_solve, newton, tangent_at, point_info, metric_dot, gap_constraint, jacobian_free
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_branch_types, only: grow
   implicit none
   private

   public :: lj_branch_type, lj_trace_options, lj_trace, lj_point_at, branch_append, &
      fold_crossing
   public :: lj_event_none, lj_event_load_fold, lj_event_gap_fold, &
      lj_event_full_contact, lj_event_contact, lj_event_end

   !> Events of a traced point: 0 none, 1 fold of P* (extremum +1 maximum, -1 minimum),
   !> 14 fold of gbar* (extremum +2 maximum, -2 minimum), 5 a* reaches or leaves 1/2
   !> (h_max = eps), 15 contact made or lost (h_min = eps), 8 first and last point.
   integer, parameter :: lj_event_none = 0, lj_event_load_fold = 1, lj_event_gap_fold = 14, &
      lj_event_full_contact = 5, lj_event_contact = 15, lj_event_end = 8

   !> The traced curve, in the order of the trace (arclength s increasing).
   type :: lj_branch_type
      integer :: n = 0
      !> Grid points per period and unknowns per state
      integer :: n_period = 0, n_unknowns = 0
      real(wp), allocatable :: s(:), p_star(:), gbar(:), a_star(:), b_star(:), &
         h_min(:), h_max(:)
      !> dP*/ds and dgbar*/ds along the trace
      real(wp), allocatable :: dp(:), dg(:)
      !> Negative eigenvalues of the energy's Hessian under load and gap control, and
      !> stability (none negative)
      integer, allocatable :: neg_load(:), neg_gap(:)
      logical, allocatable :: stable_load(:), stable_gap(:)
      integer, allocatable :: event(:), extremum(:)
      !> The states z = (gaps at the unknown nodes, P*) and unit tangents, by column
      real(wp), allocatable :: z(:, :), t(:, :)
      !> Linear systems factorised during the trace (a cost measure)
      integer :: n_factor = 0
   end type lj_branch_type

   !> Continuation controls.
   type :: lj_trace_options
      !> Largest turn of the tangent per step [rad]; largest change of P*, gbar* per step in
      !> units of the load scale max(1, sigma_peak/2) and the gap scale max(1, eps) of the
      !> law (over p* and Delta: 1 and 1 unless the law is strong or long-ranged)
      real(wp) :: max_turn = 0.15_wp, dp_max = 0.05_wp, dg_max = 0.05_wp
      !> The trace starts with the crest gap at far_start times eps
      real(wp) :: far_start = 500.0_wp
      !> The trace ends this far in P* beyond where full contact is first reached
      real(wp) :: p_beyond = 0.25_wp
      integer :: max_points = 20000
   end type lj_trace_options

   !> An accepted point of the trace with its factorised Hessian.
   type :: trace_point
      real(wp), allocatable :: z(:), t(:)
      type(point_info_type) :: info
      real(wp) :: s = 0.0_wp
      !> negative eigenvalues under load and gap control
      integer :: neg_load = 0, neg_gap = 0
   end type trace_point

   real(wp), parameter :: ds_min = 1.0e-12_wp

contains

   !> Trace the equilibrium curve of problem from far apart to full contact.
   subroutine lj_trace(problem, branch, status, errmsg, options)
      !> The discretised problem made by lj_problem (status wa_ok)
      type(lj_problem_type), intent(in) :: problem
      !> The traced curve: P*, gbar* (over Delta), a*, b*, h_min, h_max, tangents, inertia,
      !> stability, events and states z at every point; on failure the points traced so far
      !> (n = 0 where the state far apart did not converge)
      type(lj_branch_type), intent(out) :: branch
      !> wa_ok; wa_not_converged where the state far apart does not converge or the step
      !> falls below 1e-12 (a singular point of the curve); wa_capacity_too_small where
      !> the branch reaches options%max_points points before the trace's end
      integer, intent(out) :: status
      !> Receives the reason on failure (what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> Continuation controls (lj_trace_options: largest turn and changes of P*, gbar* per
      !> step, start and end of the trace, max_points), used as given; absent: the defaults
      type(lj_trace_options), intent(in), optional :: options
      type(jacobian_type) :: pre
      call trace_with(problem, pre, branch, status, errmsg, options)
      call jacobian_free(pre)
   end subroutine lj_trace

   !> lj_trace with the caller's workspace pre.
   subroutine trace_with(problem, pre, branch, status, errmsg, options)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: pre
      type(lj_branch_type), intent(out) :: branch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(lj_trace_options), intent(in), optional :: options
      type(lj_trace_options) :: opts
      type(trace_point) :: cur, nxt
      real(wp) :: ds, turn, eps, p_fc, p_scale, g_scale, peak, slope
      integer :: n, iters, n_before, factor_before
      logical :: accept, done

      if (present(options)) opts = options
      n = problem%grid%n
      eps = law_zero(problem%law)
      ! the scales of the load and the mean gap along the trace: the fully adhered branch
      ! holds a tension of the order of the peak (P_pf* = -236 at a peak of 237, alpha
      ! 34.8, mu 21.9), and the gap varies on the law's range where that exceeds Delta
      call law_eval(problem%law, law_peak(problem%law), peak, slope)
      p_scale = max(1.0_wp, 0.5_wp*peak)
      g_scale = max(1.0_wp, eps)
      branch%n_period = problem%grid%n_period
      branch%n_unknowns = n
      call far_point(problem, opts, cur, pre, branch%n_factor, status, errmsg)
      if (status /= wa_ok) return
      call branch_append(problem, branch, cur%z, cur%t, cur%info, cur%s, cur%neg_load, &
         cur%neg_gap, lj_event_end, 0)
      ds = 0.25_wp*cur%info%h_min
      p_fc = huge(1.0_wp)
      done = .false.
      do while (.not. done)
         ds = min(ds, step_cap(cur%info, eps, max(p_scale, g_scale)))
         factor_before = branch%n_factor
         call advance(problem, cur, ds, nxt, pre, iters, branch%n_factor, status)
         accept = status == wa_ok
         if (accept) then
            turn = acos(max(-1.0_wp, min(1.0_wp, metric_dot(problem, cur%t, nxt%t))))
            accept = turn <= opts%max_turn .and. &
               abs(nxt%info%p - cur%info%p) <= opts%dp_max*p_scale .and. &
               (abs(nxt%info%gbar - cur%info%gbar) <= opts%dg_max*g_scale .or. &
               cur%info%h_min > 2*eps)
         end if
         if (.not. accept) then
            ds = 0.5_wp*ds
            if (ds < ds_min) then
               call set_error(wa_not_converged, "lj_trace: the continuation step fell below "// &
                  "1e-12 (a singular point of the curve?)", status, errmsg)
               return
            end if
            cycle
         end if
         n_before = branch%n
         call locate_events(problem, cur, nxt, pre, branch)
         ! the inertia changes only at folds (located above): refresh it where the step
         ! held an event or the preconditioner was rebuilt away from the curve's points
         if (branch%n > n_before .or. branch%n_factor > factor_before) then
            call factor_at(problem, nxt%z, pre)
            branch%n_factor = branch%n_factor + 1
            if (problem%two_grid) then          ! counted across the step's folds
               if (branch%n > n_before) then
                  nxt%neg_load = branch%neg_load(branch%n)
                  nxt%neg_gap = branch%neg_gap(branch%n)
               end if
            else
               nxt%neg_load = pre%neg_load
               nxt%neg_gap = pre%neg_gap
            end if
         end if
         if (nxt%info%h_max <= eps .and. p_fc == huge(1.0_wp)) p_fc = max(nxt%info%p, 0.0_wp)
         done = nxt%info%h_max <= eps .and. nxt%neg_load == 0 .and. nxt%neg_gap == 0 &
            .and. nxt%t(n + 1) > 0.0_wp .and. nxt%info%p >= p_fc + opts%p_beyond
         call branch_append(problem, branch, nxt%z, nxt%t, nxt%info, nxt%s, nxt%neg_load, &
            nxt%neg_gap, merge(lj_event_end, lj_event_none, done), 0)
         call move_point(nxt, cur)
         if (branch%n >= opts%max_points) then
            call set_error(wa_capacity_too_small, "lj_trace: more than max_points points "// &
               "before full contact", status, errmsg)
            return
         end if
         if (iters < huge(iters) .and. turn < 0.5_wp*opts%max_turn) ds = 1.5_wp*ds
      end do
      status = wa_ok
   end subroutine trace_with

   !> Largest step from a point: far apart a quarter of the crest gap (the load varies on
   !> that scale), else 0.1 times the larger of the load and gap scales (the other
   !> controls bound it).
   pure function step_cap(info, eps, scale) result(ds)
      type(point_info_type), intent(in) :: info
      real(wp), intent(in) :: eps, scale
      real(wp) :: ds
      ds = max(0.25_wp*info%h_min, 4.0_wp*eps)
      if (info%h_min < 4.0_wp*eps) ds = 0.1_wp*scale
   end function step_cap

   !> The first point: the crest gap far_start eps, solved at that mean gap; the
   !> tangent points to smaller mean gaps. pre: the Hessian factorised there.
   subroutine far_point(problem, opts, pt, pre, n_factor, status, errmsg)
      type(lj_problem_type), intent(in) :: problem
      type(lj_trace_options), intent(in) :: opts
      type(trace_point), intent(out) :: pt
      type(jacobian_type), intent(inout) :: pre
      integer, intent(inout) :: n_factor
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), allocatable :: zero(:)
      real(wp) :: gbar, y
      integer :: n
      n = problem%grid%n
      allocate (pt%z(n + 1), pt%t(n + 1), zero(n))
      pt%z(1:n) = problem%grid%f - minval(problem%grid%f) + opts%far_start*law_zero(problem%law)
      pt%z(n + 1) = 0.0_wp
      gbar = sum(problem%grid%w*pt%z(1:n))/problem%grid%n_period
      call factor_at(problem, pt%z, pre)
      n_factor = n_factor + 1
      call newton(problem, gap_constraint(problem), gbar, pt%z, pre, status, n_factor)
      if (status /= wa_ok) then
         call set_error(wa_not_converged, "lj_trace: no converged state far apart", status, &
            errmsg)
         return
      end if
      call factor_at(problem, pt%z, pre)
      n_factor = n_factor + 1
      pt%neg_load = pre%neg_load
      pt%neg_gap = pre%neg_gap
      zero = 0.0_wp
      call bordered_solve(problem, pre, gap_constraint(problem), zero, -1.0_wp, &
         pt%t(1:n), y)
      pt%t(n + 1) = y
      pt%t = pt%t/sqrt(metric_dot(problem, pt%t, pt%t))
      pt%info = point_info(problem, pt%z)
   end subroutine far_point

   !> One predictor-corrector step of length ds from cur (status /= wa_ok: refused); the
   !> inertia is carried over (lj_trace refreshes it where it may change).
   subroutine advance(problem, cur, ds, nxt, pre, iters, n_factor, status)
      type(lj_problem_type), intent(in) :: problem
      type(trace_point), intent(in) :: cur
      real(wp), intent(in) :: ds
      type(trace_point), intent(inout) :: nxt
      type(jacobian_type), intent(inout) :: pre
      integer, intent(out) :: iters, status
      integer, intent(inout) :: n_factor
      real(wp), allocatable :: a(:)
      integer :: n, nf0
      n = problem%grid%n
      allocate (a(n + 1))
      a(1:n) = problem%grid%w*cur%t(1:n)/problem%grid%n_period
      a(n + 1) = cur%t(n + 1)
      nxt%z = cur%z + ds*cur%t
      nf0 = n_factor
      call newton(problem, a, dot_product(a, nxt%z), nxt%z, pre, status, n_factor, iters)
      if (n_factor > nf0) iters = huge(iters)     ! the corrector needed a new Jacobian
      if (status /= wa_ok) return
      if (.not. allocated(nxt%t)) allocate (nxt%t(n + 1))
      call tangent_at(problem, pre, nxt%z, cur%t, nxt%t, n_factor)
      nxt%info = point_info(problem, nxt%z)
      nxt%s = cur%s + ds
      nxt%neg_load = cur%neg_load
      nxt%neg_gap = cur%neg_gap
   end subroutine advance

   subroutine move_point(from, to)
      type(trace_point), intent(inout) :: from, to
      call move_alloc(from%z, to%z)
      call move_alloc(from%t, to%t)
      to%info = from%info
      to%s = from%s
      to%neg_load = from%neg_load
      to%neg_gap = from%neg_gap
   end subroutine move_point

   !> Value of event function kind at a point: 1 dP/ds, 2 dgbar/ds, 3 h_max - eps,
   !> 4 h_min - eps.
   pure function event_value(problem, kind, pt) result(v)
      type(lj_problem_type), intent(in) :: problem
      integer, intent(in) :: kind
      type(trace_point), intent(in) :: pt
      real(wp) :: v
      integer :: n
      n = problem%grid%n
      select case (kind)
      case (1); v = pt%t(n + 1)
      case (2); v = sum(problem%grid%w*pt%t(1:n))/problem%grid%n_period
      case (3); v = pt%info%h_max - law_zero(problem%law)
      case default; v = pt%info%h_min - law_zero(problem%law)
      end select
   end function event_value

   !> Locate the events between cur and nxt (sign changes of the event functions) and
   !> append them to the branch in the order of s.
   subroutine locate_events(problem, cur, nxt, pre, branch)
      type(lj_problem_type), intent(in) :: problem
      type(trace_point), intent(in) :: cur, nxt
      type(jacobian_type), intent(inout) :: pre
      type(lj_branch_type), intent(inout) :: branch
      type(trace_point) :: found(4)
      integer :: kinds(4), order(4), nf, kind, i, j, ev, ext, status, neg_load, neg_gap
      real(wp) :: f0, f1
      nf = 0
      do kind = 1, 4
         f0 = event_value(problem, kind, cur)
         f1 = event_value(problem, kind, nxt)
         if (f0*f1 < 0.0_wp) then
            nf = nf + 1
            kinds(nf) = kind
            call locate_one(problem, kind, cur, nxt, f0, f1, pre, found(nf), branch%n_factor, &
               status)
            if (status /= wa_ok) nf = nf - 1     ! (not found: the step's ends bracket it)
         end if
      end do
      order(1:nf) = [(i, i = 1, nf)]
      do i = 2, nf                                 ! insertion sort on s
         j = i
         do while (j > 1)
            if (found(order(j - 1))%s <= found(order(j))%s) exit
            order([j - 1, j]) = order([j, j - 1])
            j = j - 1
         end do
      end do
      neg_load = cur%neg_load
      neg_gap = cur%neg_gap
      do i = 1, nf
         associate (pt => found(order(i)), kind => kinds(order(i)))
            select case (kind)
            case (1)
               ev = lj_event_load_fold
               ext = merge(1, -1, event_value(problem, 1, cur) > 0.0_wp)
               neg_load = max(neg_load + fold_crossing(problem, pt%z, pt%t), 0)
            case (2)
               ev = lj_event_gap_fold
               ext = merge(2, -2, event_value(problem, 2, cur) > 0.0_wp)
               neg_gap = max(neg_gap + fold_crossing(problem, pt%z, pt%t), 0)
            case (3)
               ev = lj_event_full_contact; ext = 0
            case default
               ev = lj_event_contact; ext = 0
            end select
            if (problem%two_grid) then
               pt%neg_load = neg_load
               pt%neg_gap = neg_gap
            end if
            call branch_append(problem, branch, pt%z, pt%t, pt%info, pt%s, pt%neg_load, &
               pt%neg_gap, ev, ext)
         end associate
      end do
   end subroutine locate_events

   !> Brent on the event function along the step from cur to nxt; the point found gets
   !> its inertia from a factorisation there (pre is left factorised at it).
   subroutine locate_one(problem, kind, cur, nxt, f0, f1, pre, pt, n_factor, status)
      type(lj_problem_type), intent(in) :: problem
      integer, intent(in) :: kind
      type(trace_point), intent(in) :: cur, nxt
      real(wp), intent(in) :: f0, f1
      type(jacobian_type), intent(inout) :: pre
      type(trace_point), intent(inout) :: pt
      integer, intent(inout) :: n_factor
      integer, intent(out) :: status
      type(brent_type) :: solver
      real(wp) :: s, ds
      integer :: it
      logical :: done
      ds = nxt%s - cur%s
      call brent_init(solver, 0.0_wp, f0, ds, f1, 1.0e-11_wp*ds)
      status = wa_not_converged
      do it = 1, 60
         call brent_propose(solver, s, done, settle=.true.)
         if (done) exit
         call lj_point_at(problem, cur%z, cur%t, pre, s, pt%z, pt%t, n_factor, status)
         if (status /= wa_ok) return
         pt%info = point_info(problem, pt%z)
         call brent_accept(solver, event_value(problem, kind, pt))
      end do
      if (.not. done) return
      call lj_point_at(problem, cur%z, cur%t, pre, solver%b, pt%z, pt%t, n_factor, status)
      if (status /= wa_ok) return
      pt%info = point_info(problem, pt%z)
      pt%s = cur%s + solver%b
      call factor_at(problem, pt%z, pre)
      n_factor = n_factor + 1
      pt%neg_load = pre%neg_load
      pt%neg_gap = pre%neg_gap
   end subroutine locate_one

   !> The point at arclength s beyond (z0, t0) on the curve and its tangent (oriented
   !> along t0); pre: a Hessian factorised near z0 (the preconditioner, may be rebuilt).
   subroutine lj_point_at(problem, z0, t0, pre, s, z, t, n_factor, status)
      type(lj_problem_type), intent(in) :: problem
      real(wp), intent(in) :: z0(:), t0(:), s
      type(jacobian_type), intent(inout) :: pre
      real(wp), allocatable, intent(inout) :: z(:), t(:)
      integer, intent(inout) :: n_factor
      integer, intent(out) :: status
      real(wp), allocatable :: a(:)
      integer :: n
      n = problem%grid%n
      allocate (a(n + 1))
      a(1:n) = problem%grid%w*t0(1:n)/problem%grid%n_period
      a(n + 1) = t0(n + 1)
      z = z0 + s*t0
      call newton(problem, a, dot_product(a, z), z, pre, status, n_factor)
      if (status /= wa_ok) return
      if (.not. allocated(t)) allocate (t(n + 1))
      call tangent_at(problem, pre, z, t0, t, n_factor)
   end subroutine lj_point_at

   !> Change of the count of negative eigenvalues across a simple fold at (z, t) of the
   !> control whose Hessian is singular there: -sign(sum(w sigma''(h) t_h^3)).
   pure integer function fold_crossing(problem, z, t)
      type(lj_problem_type), intent(in) :: problem
      real(wp), intent(in) :: z(:), t(:)
      integer :: n
      n = problem%grid%n
      fold_crossing = -1
      if (sum(problem%grid%w*law_curvature(problem%law, z(1:n))*t(1:n)**3) < 0.0_wp) &
         fold_crossing = 1
   end function fold_crossing

   !> Append a point to the branch (arrays grown by doubling).
   subroutine branch_append(problem, branch, z, t, info, s, neg_load, neg_gap, event, extremum)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      real(wp), intent(in) :: z(:), t(:), s
      type(point_info_type), intent(in) :: info
      integer, intent(in) :: neg_load, neg_gap, event, extremum
      integer :: k, n
      n = size(z) - 1
      if (.not. allocated(branch%s)) call reserve(branch, 64, n + 1)
      if (branch%n == size(branch%s)) call reserve(branch, 2*size(branch%s), n + 1)
      k = branch%n + 1
      branch%n = k
      branch%s(k) = s
      branch%p_star(k) = info%p
      branch%gbar(k) = info%gbar
      branch%a_star(k) = info%a_star
      branch%b_star(k) = info%b_star
      branch%h_min(k) = info%h_min
      branch%h_max(k) = info%h_max
      branch%dp(k) = t(n + 1)
      branch%dg(k) = sum(problem%grid%w*t(1:n))/problem%grid%n_period
      branch%neg_load(k) = neg_load
      branch%neg_gap(k) = neg_gap
      branch%stable_load(k) = neg_load == 0 .and. extremum == 0
      branch%stable_gap(k) = neg_gap == 0 .and. extremum == 0
      branch%event(k) = event
      branch%extremum(k) = extremum
      branch%z(:, k) = z
      branch%t(:, k) = t
   end subroutine branch_append

   subroutine reserve(branch, cap, m)
      type(lj_branch_type), intent(inout) :: branch
      integer, intent(in) :: cap, m
      call grow(branch%s, branch%n, cap); call grow(branch%p_star, branch%n, cap)
      call grow(branch%gbar, branch%n, cap); call grow(branch%a_star, branch%n, cap)
      call grow(branch%b_star, branch%n, cap); call grow(branch%h_min, branch%n, cap)
      call grow(branch%h_max, branch%n, cap); call grow(branch%dp, branch%n, cap)
      call grow(branch%dg, branch%n, cap); call grow(branch%neg_load, branch%n, cap)
      call grow(branch%neg_gap, branch%n, cap); call grow(branch%stable_load, branch%n, cap)
      call grow(branch%stable_gap, branch%n, cap); call grow(branch%event, branch%n, cap)
      call grow(branch%extremum, branch%n, cap)
      call grow_2(branch%z); call grow_2(branch%t)
   contains
      subroutine grow_2(v)
         real(wp), allocatable, intent(inout) :: v(:, :)
         real(wp), allocatable :: tmp(:, :)
         allocate (tmp(m, cap))
         if (allocated(v)) tmp(:, 1:branch%n) = v(:, 1:branch%n)
         call move_alloc(tmp, v)
      end subroutine grow_2
   end subroutine reserve

end module wa_bem_trace
