!> The traced branch as data: its points (a*, c*, P*, gbar*, zone case, stability, event,
!> extremum) in the order of the curve, the continuation's options, and the growth of the
!> point arrays (append, reserve). wa_branch fills it (trace_branch) and defines the
!> event codes.
module wa_branch_types
   use wa_kinds, only: wp
   use wa_state, only: state_type
   implicit none
   private

   public :: branch_type, trace_options, append, reserve, grow

   !> Grow an allocatable array to `capacity`, keeping its first n entries
   interface grow
      module procedure grow_real, grow_int, grow_logical
   end interface grow

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

contains

   !> Add state s as the branch's next point (growing the arrays twofold when full).
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

   !> Room for `capacity` points, keeping the branch%n stored (none if unallocated).
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

end module wa_branch_types
