!> One state of the smooth-adhesion (Lennard-Jones) model at a given contact half-width:
!> the gap and traction fields over the period, as every face draws them (the Fortran
!> routine behind the C wa_lj_profile, the Python profile("lj", ...) and the CLI's
!> `profile --model lj`; doc/theory.md, "Smooth adhesion").
!>
!> a* is half the measure of {h <= eps} (the contact: the gap inside the repulsive part of
!> the law), so it is a function of the state, not a coordinate of the curve: the curve
!> is traced (lj_trace) and the state drawn is the traced point with a* nearest the target
!> among the load-stable points (all points when none is load-stable), the first such
!> point in the order of the trace on a tie (lj_nearest_state). The state is therefore
!> one the load-controlled path can rest on; a* between two traced points is not
!> interpolated (the point's own a* is returned).
module wa_bem_state
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   use wa_validate, only: check_range
   use wa_bem_law, only: law_eval
   use wa_bem_elastic, only: full_period
   use wa_bem_solver, only: lj_problem_type
   use wa_bem_trace, only: lj_branch_type, lj_trace
   implicit none
   private

   public :: lj_state_type, lj_state_at_a, lj_nearest_state, lj_profile

   !> One traced state and its fields at the N grid nodes, x* from -1/2.
   type :: lj_state_type
      !> Grid points per period N (the number of points of the fields)
      integer :: n_period = 0
      !> The state: contact half-width a*, b* (half the measure of {h <= 3^(1/6) eps}, the
      !> position of the peak tension), load P* (over p*) and mean gap gbar* (over Delta)
      real(wp) :: a_star = 0.0_wp, b_star = 0.0_wp, p_star = 0.0_wp, gbar = 0.0_wp
      !> Stable under load control, under gap control (stable_load false only where the
      !> traced curve has no load-stable point at all)
      logical :: stable_load = .false., stable_gap = .false.
      !> Node positions x* = j/N - 1/2, j = 0..N-1 (crest at x* = 0)
      real(wp), allocatable :: x(:)
      !> Gap h/Delta at x* (>= 0: the law is repulsive below eps)
      real(wp), allocatable :: gap(:)
      !> Traction p/p* at x* (positive = compressive, as the other models' profiles)
      real(wp), allocatable :: traction(:)
   end type lj_state_type

contains

   !> The traced state of problem with a* nearest a_star (among the load-stable ones when
   !> there are any; the first on a tie) and its gap and traction at the N grid nodes,
   !> written from x* = -1/2 on. Thread safe (no state kept between calls).
   subroutine lj_state_at_a(problem, a_star, state, status, errmsg)
      !> The discretised problem made by lj_problem (status wa_ok): law, grid, profile
      type(lj_problem_type), intent(in) :: problem
      !> The contact half-width wanted, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> The state drawn and its fields; on failure n_period = 0 and the fields unallocated
      type(lj_state_type), intent(out) :: state
      !> wa_ok; wa_invalid_argument where a_star is outside [0, 1/2] or NaN (checked before
      !> the trace); else the failure of lj_trace (wa_not_converged, wa_capacity_too_small
      !> where the curve exceeds its points cap)
      integer, intent(out) :: status
      !> Receives the reason on failure (the argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(lj_branch_type) :: branch
      real(wp), allocatable :: xs(:), hs(:), ss(:)
      integer :: i, j, k, np

      call check_range("a_star", a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return                  ! before the costly trace
      call lj_trace(problem, branch, status, errmsg)
      if (status /= wa_ok) return
      call lj_nearest_state(branch, a_star, k, status, errmsg)
      if (status /= wa_ok) return
      np = branch%n_period
      allocate (xs(np), hs(np), ss(np), state%x(np), state%gap(np), state%traction(np))
      call lj_profile(problem, branch%z(:, k), xs, hs, ss)
      do i = 1, np                         ! x* = j/N from -1/2 (node N/2) on
         j = modulo(i - 1 + np/2, np) + 1
         state%x(i) = xs(j) - merge(1.0_wp, 0.0_wp, xs(j) >= 0.5_wp)
         state%traction(i) = -ss(j)
         state%gap(i) = hs(j)
      end do
      state%n_period = np
      state%a_star = branch%a_star(k)
      state%b_star = branch%b_star(k)
      state%p_star = branch%p_star(k)
      state%gbar = branch%gbar(k)
      state%stable_load = branch%stable_load(k)
      state%stable_gap = branch%stable_gap(k)
   end subroutine lj_state_at_a

   !> The traced state with a* nearest a_star, among the load-stable states when there
   !> are any (the state a profile draws); the first such point on a tie.
   pure subroutine lj_nearest_state(branch, a_star, k, status, errmsg, among_stable)
      !> A curve traced by lj_trace (n >= 1 points)
      type(lj_branch_type), intent(in) :: branch
      !> The contact half-width a* wanted, in [0, 1/2]
      real(wp), intent(in) :: a_star
      !> Index of the chosen point in branch (1..branch%n); 0 on failure
      integer, intent(out) :: k
      !> wa_ok; wa_invalid_argument where a_star is outside [0, 1/2] (or NaN) or the
      !> branch has no point
      integer, intent(out) :: status
      !> Receives the reason on failure (the argument and its valid range)
      character(len=*), intent(inout), optional :: errmsg
      !> True where the choice was among the load-stable states (there are some)
      logical, intent(out), optional :: among_stable
      real(wp) :: miss
      integer :: i
      logical :: any_stable

      k = 0
      if (present(among_stable)) among_stable = .false.
      if (.not. (a_star >= 0.0_wp .and. a_star <= 0.5_wp)) then
         call set_error(wa_invalid_argument, "a_star is outside its valid range [0, 1/2]", &
            status, errmsg)
         return
      end if
      if (branch%n < 1) then
         call set_error(wa_invalid_argument, "branch has no point (n < 1): trace it first", &
            status, errmsg)
         return
      end if
      status = wa_ok
      any_stable = any(branch%stable_load(1:branch%n))
      if (present(among_stable)) among_stable = any_stable
      miss = huge(1.0_wp)
      do i = 1, branch%n
         if (any_stable .and. .not. branch%stable_load(i)) cycle
         if (abs(branch%a_star(i) - a_star) < miss) then
            miss = abs(branch%a_star(i) - a_star)
            k = i
         end if
      end do
      ! a NaN a* everywhere would leave no choice: take the first candidate
      if (k == 0) k = merge(findloc(branch%stable_load(1:branch%n), .true., dim=1), 1, &
         any_stable)
   end subroutine lj_nearest_state

   !> Gap h/Delta and traction sigma/p* (tension positive) of state z over the whole
   !> period, at x = j/N, j = 0..N-1.
   pure subroutine lj_profile(problem, z, x, gap, traction)
      !> The problem the state was traced for (N = its grid points per period)
      type(lj_problem_type), intent(in) :: problem
      !> A state of that problem, e.g. a column of lj_branch_type%z: the gaps over Delta at
      !> the n_unknowns unknown nodes, then P*; only the gaps are read
      real(wp), intent(in) :: z(:)
      !> Receives the node positions x* = j/N, j = 0..N-1 (size N)
      real(wp), intent(out) :: x(:)
      !> Receives the gap h/Delta at x* over the whole period (an even state unfolded; size N)
      real(wp), intent(out) :: gap(:)
      !> Receives the traction sigma(h)/p* of the law at x* (tension positive; size N)
      real(wp), intent(out) :: traction(:)
      real(wp), allocatable :: slope(:)
      integer :: j, np
      np = problem%grid%n_period
      allocate (slope(np))
      x = [(real(j, wp)/np, j = 0, np - 1)]
      gap = full_period(problem%grid, z(1:problem%grid%n))
      call law_eval(problem%law, gap, traction, slope)
   end subroutine lj_profile

end module wa_bem_state
