!> The adhesion map's data: the map (grids, region mechanisms, boundary curves, special
!> points), the codes of a curve's ends and of the special points, and their meanings as
!> text. wa_map builds it (adhesion_map).
module wa_map_types
   use wa_kinds, only: wp
   use wa_text, only: int_text
   use wa_gapmech, only: gap_mechanism_name
   implicit none
   private

   public :: map_type, map_boundary, boundary_code, boundary_meaning
   public :: map_end_grid, map_end_inside, map_end_mu_range, map_end_failed
   public :: map_point, special_meaning, map_point_meet, map_point_turn, map_point_end, &
      map_point_fail
   public :: map_control_load, map_control_gap, map_control_both

   !> What the map locates (adhesion_map's `control`): the load-control boundaries (which 1
   !> full contact, 2 pull-off), the gap-control ones (which 3 approach, 4 retraction:
   !> wa_gapmech), or both
   integer, parameter :: map_control_load = 1, map_control_gap = 2, map_control_both = 3

   !> How a boundary curve starts or ends: at the first/last alpha of the grid; inside the
   !> grid (it meets another boundary, or the region it bounds closes: located to 1e-6
   !> relative in alpha); where it leaves [mu_lo, mu_hi]; where the load path fails.
   integer, parameter :: map_end_grid = 0, map_end_inside = 1, map_end_mu_range = 2, &
      map_end_failed = 3

   !> One boundary curve: code = 100*which + 10*mech_below + mech_above (which: 1 full
   !> contact, 2 pull-off, 3 gap approach, 4 gap retraction; mech_*: mechanism_* codes
   !> (which 1, 2) or wa_gapmech's codes (3, 4) just below / above the curve in mu).
   type :: map_boundary
      integer :: code = 0, which = 0, mech_below = -1, mech_above = -1
      integer :: n = 0
      !> Points in increasing alpha (the grid values, plus located ends off the grid)
      real(wp), allocatable :: alpha(:), mu(:)
      !> map_end_* codes of the first and the last point
      integer :: start_kind = map_end_grid, end_kind = map_end_grid
   end type map_boundary

   !> Special points: where boundaries meet (an end of one curve on another curve or at
   !> another's end), where a boundary turns back in alpha (the ends of a curve and of its
   !> reverse, e.g. 212 and 221, coincide: the region between them closes), where one
   !> ends alone (its region closes), and where the load path fails.
   integer, parameter :: map_point_meet = 1, map_point_turn = 2, map_point_end = 3, &
      map_point_fail = 4

   !> A special point of the map: kind (map_point_*), where, and the boundary codes
   !> involved (codes(2) = 0 when only one).
   type :: map_point
      integer :: kind = 0
      real(wp) :: alpha = 0.0_wp, mu = 0.0_wp
      integer :: codes(2) = 0
   end type map_point

   !> The map: the grids, the mechanisms in every cell, the boundary curves.
   type :: map_type
      integer :: model = 0
      !> map_control_* (which boundaries and regions are computed)
      integer :: control = map_control_load
      real(wp), allocatable :: alpha(:), mu(:)
      !> Full-contact and pull-off mechanism at (mu(i), alpha(j)); -1 where the load path
      !> fails on a scanned alpha
      integer, allocatable :: fc_region(:, :), pf_region(:, :)
      !> Gap approach and retraction mechanism (wa_gapmech) at (mu(i), alpha(j)); -1 where
      !> the cycle fails or the map does not compute gap control
      integer, allocatable :: ga_region(:, :), gr_region(:, :)
      integer :: n_boundaries = 0
      type(map_boundary), allocatable :: boundary(:)
      !> Load paths computed (the cost of the map)
      integer :: n_paths = 0
      !> Where boundaries meet, turn back, end or fail inside the grid (special_meaning)
      integer :: n_special = 0
      type(map_point), allocatable :: special(:)
   end type map_type

contains

   !> The boundary code of a change of mechanism `which` (1 full contact, 2 pull-off)
   !> from mech_below to mech_above as mu grows.
   pure integer function boundary_code(which, mech_below, mech_above)
      !> Which mechanism changes: 1 full contact, 2 pull-off (load control), 3 approach,
      !> 4 retraction (gap control)
      integer, intent(in) :: which
      !> The mechanism just below the boundary in mu (mechanism_* codes for which 1, 2;
      !> gap_mechanisms' codes for 3, 4), in 0..3
      integer, intent(in) :: mech_below
      !> The mechanism just above the boundary in mu (same codes), in 0..3
      integer, intent(in) :: mech_above
      boundary_code = 100*which + 10*mech_below + mech_above
   end function boundary_code

   !> "full contact: gradual -> jump case 1" and the like, for a boundary code.
   pure function boundary_meaning(code) result(text)
      !> A boundary code, 100*which + 10*mech_below + mech_above (boundary_code); any other
      !> value gives "unknown"
      integer, intent(in) :: code
      character(len=:), allocatable :: text
      character(len=*), parameter :: names(0:3) = [character(len=11) :: "gradual", &
         "jump case 1", "jump case 2", "snap at P=0"]
      integer :: which, lo, hi
      which = code/100
      lo = mod(code/10, 10)
      hi = mod(code, 10)
      if (which < 1 .or. which > 4 .or. lo > 3 .or. hi > 3 .or. lo == hi .or. code < 0) then
         text = "unknown"
         return
      end if
      select case (which)
      case (1)
         text = "full contact: "//trim(names(lo))//" -> "//trim(names(hi))
      case (2)
         text = "pull-off: "//trim(names(lo))//" -> "//trim(names(hi))
      case (3)
         text = "gap approach: "//gap_mechanism_name(3, lo)//" -> "//gap_mechanism_name(3, hi)
      case default
         text = "gap retraction: "//gap_mechanism_name(4, lo)//" -> "// &
            gap_mechanism_name(4, hi)
      end select
   end function boundary_meaning

   !> "pull-off: jump case 1 -> jump case 2 turns back in alpha" and the like.
   pure function special_meaning(point) result(text)
      !> A special point of a map (map_type's points): its kind and boundary codes are read
      type(map_point), intent(in) :: point
      character(len=:), allocatable :: text
      select case (point%kind)
      case (map_point_meet)
         text = boundary_meaning(point%codes(1))//" meets "// &
            boundary_meaning(point%codes(2))
      case (map_point_turn)
         text = boundary_meaning(point%codes(1))//" turns back in alpha (meets its "// &
            "reverse "//int_text(point%codes(2))//"; the region between closes)"
      case (map_point_end)
         text = boundary_meaning(point%codes(1))//" ends (its region closes)"
      case (map_point_fail)
         text = boundary_meaning(point%codes(1))//": the load path fails here"
      case default
         text = "unknown"
      end select
   end function special_meaning

end module wa_map_types
