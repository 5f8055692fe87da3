!> The adhesion map (wa_map): boundary points agree with mechanism_change's bisection to
!> 1e-8 relative in mu, codes and meanings, regions on each side, invalid arguments.
module test_map
   use harness, only: error_type, unittest_type, new_unittest, check
   use wavyadhesion
   use wa_kinds, only: wp
   use wa_map, only: map_n_mu_max, map_n_alpha_max, map_cells_max
   implicit none
   private

   public :: collect_map

contains

   subroutine collect_map(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("dw_points_equal_mechanism_change_20_alpha", test_dw_points), &
         new_unittest("md_points_equal_mechanism_change", test_md_points), &
         new_unittest("codes_and_meanings", test_codes), &
         new_unittest("regions_match_boundaries", test_regions), &
         new_unittest("special_points_dw", test_special), &
         new_unittest("invalid_arguments", test_invalid), &
         new_unittest("dw_gap_points_equal_gap_mechanism_change_20_alpha", test_dw_gap_points), &
         new_unittest("md_gap_points_equal_gap_mechanism_change", test_md_gap_points), &
         new_unittest("gap_codes_and_meanings", test_gap_codes), &
         new_unittest("gap_regions_match_boundaries", test_gap_regions), &
         new_unittest("bisection_needs_a_change", test_no_change)]
   end subroutine collect_map

   !> A bracket with the same mechanism at both ends holds no change to bisect: status
   !> wa_no_solution, not its upper end with an OK status (as before).
   subroutine test_no_change(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: mu
      integer :: status
      call mechanism_change(model_dw, 0.3_wp, 1, 0.01_wp, 0.02_wp, mu, status)
      call check(error, status == wa_no_solution, "load control: no change in [0.01, 0.02]")
      if (allocated(error)) return
      call gap_mechanism_change(model_md, 0.3_wp, 3, 0.1_wp, 0.158_wp, mu, status)
      call check(error, status == wa_no_solution, "gap control: no change in [0.1, 0.158]")
      if (allocated(error)) return
      call gap_mechanism_change(model_md, 0.3_wp, 3, 0.158_wp, 0.16_wp, mu, status)
      call check(error, status == wa_ok .and. abs(mu/0.1589_wp - 1.0_wp) < 1.0e-3_wp, &
         "gap control: 302 in [0.158, 0.16]")
   end subroutine test_no_change

   !> 20 alpha over [0.01, 10]: every boundary point on the grid, rebisected by
   !> mechanism_change from a bracket of +-1e-7 around it, agrees to 1e-8 relative, on
   !> every boundary (201/210 too: the pull-off mechanism no longer flickers there, see
   !> a_point_pull_off in wa_mechanism).
   subroutine test_dw_points(error)
      type(error_type), allocatable, intent(out) :: error
      call check_points(error, model_dw, 20)
   end subroutine test_dw_points

   subroutine test_md_points(error)
      type(error_type), allocatable, intent(out) :: error
      call check_points(error, model_md, 2)
   end subroutine test_md_points

   subroutine check_points(error, model, n_alpha)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in) :: model, n_alpha
      type(map_type) :: map
      real(wp) :: alpha(n_alpha), mu_c, worst, d
      character(len=200) :: text
      integer :: status, c, p, j, n_checked
      character(len=256) :: msg
      alpha = [(10.0_wp**(-2.0_wp + 3.0_wp*real(j - 1, wp)/real(n_alpha - 1, wp)), &
         j = 1, n_alpha)]
      if (n_alpha == 2) alpha = [0.1_wp, 0.11_wp]     ! MD: two near alpha keep it fast
      msg = ""
      call adhesion_map(model, alpha, 1.0e-2_wp, 1.0e2_wp, 40, map, status, msg, &
         scan_every=max(1, n_alpha/4))
      call check(error, status == wa_ok, "map: "//trim(msg))
      if (allocated(error)) return
      call check(error, map%n_boundaries >= 3, "at least three boundaries")
      if (allocated(error)) return
      worst = 0.0_wp
      n_checked = 0
      do c = 1, map%n_boundaries
         associate (b => map%boundary(c))
            do p = 1, b%n
               if (.not. any(alpha == b%alpha(p))) cycle
               call mechanism_change(model, b%alpha(p), b%which, b%mu(p)*(1.0_wp - 1.0e-7_wp), &
                  b%mu(p)*(1.0_wp + 1.0e-7_wp), mu_c, status)
               write (text, '(a,i0,a,es24.16,a,es24.16,a,i0)') "mechanism_change converges: code ", &
                  b%code, " alpha ", b%alpha(p), " mu ", b%mu(p), " status ", status
               call check(error, status == wa_ok, trim(text))
               if (allocated(error)) return
               d = abs(mu_c - b%mu(p))/b%mu(p)
               worst = max(worst, d)
               n_checked = n_checked + 1
            end do
         end associate
      end do
      call check(error, n_checked >= 2*n_alpha, "points checked")
      call check(error, worst <= 1.0e-8_wp, "boundary points agree with mechanism_change")
   end subroutine check_points

   subroutine test_codes(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, boundary_code(1, mechanism_gradual, mechanism_jump_case1) == 101, &
         "code 101")
      call check(error, boundary_meaning(101) == "full contact: gradual -> jump case 1", &
         "meaning of 101")
      call check(error, boundary_meaning(212) == "pull-off: jump case 1 -> jump case 2", &
         "meaning of 212")
      call check(error, boundary_meaning(103) == "full contact: gradual -> snap at P=0", &
         "meaning of 103")
      call check(error, boundary_meaning(7) == "unknown", "unknown code")
   end subroutine test_codes

   !> At alpha = 0.1 and 3 (DW) the region grid holds mech_below just under each boundary
   !> and mech_above just over it (between grid rows that straddle it).
   subroutine test_regions(error)
      type(error_type), allocatable, intent(out) :: error
      type(map_type) :: map
      integer :: status
      call adhesion_map(model_dw, [0.1_wp, 0.2_wp, 3.0_wp], 1.0e-3_wp, 1.0e3_wp, 40, map, &
         status, scan_every=2)
      call check(error, status == wa_ok, "map")
      if (allocated(error)) return
      call check_regions(error, map)
   end subroutine test_regions

   !> Every boundary point on the alpha grid: the region grid of its control holds
   !> mech_below in the mu row just under it and mech_above in the row just over it.
   subroutine check_regions(error, map)
      type(error_type), allocatable, intent(inout) :: error
      type(map_type), intent(in) :: map
      integer :: c, p, i, j
      integer, allocatable :: region(:, :)
      do c = 1, map%n_boundaries
         associate (b => map%boundary(c))
            select case (b%which)
            case (1)
               region = map%fc_region
            case (2)
               region = map%pf_region
            case (3)
               region = map%ga_region
            case default
               region = map%gr_region
            end select
            do p = 1, b%n
               do j = 1, size(map%alpha)
                  if (map%alpha(j) /= b%alpha(p)) cycle
                  i = count(map%mu < b%mu(p))
                  if (i < 1 .or. i >= size(map%mu)) cycle
                  call check(error, region(i, j) == b%mech_below .and. &
                     region(i + 1, j) == b%mech_above, "regions on each side of a boundary")
                  if (allocated(error)) return
               end do
            end do
         end associate
      end do
   end subroutine check_regions

   !> DW over alpha 0.3..1 (60 log values): full contact gradual -> jump case 1 (101)
   !> meets gradual -> snap (103) where the local maximum of P* reaches 0, alpha 0.5699
   !> for large mu (the JKR limit (3/4)^(3/4)/sqrt(2)); here at mu ~ 2.95, alpha within 1 %
   !> of 0.567; the pull-off boundary 212 turns back in alpha into 221 near alpha 0.878.
   subroutine test_special(error)
      type(error_type), allocatable, intent(out) :: error
      type(map_type) :: map
      real(wp) :: alpha(60)
      integer :: status, k, j
      logical :: meet, turn
      alpha = [(0.3_wp*(1.0_wp/0.3_wp)**(real(j - 1, wp)/59.0_wp), j = 1, 60)]
      call adhesion_map(model_dw, alpha, 1.0e-1_wp, 1.0e1_wp, 40, map, status, scan_every=10)
      call check(error, status == wa_ok, "map")
      if (allocated(error)) return
      meet = .false.
      turn = .false.
      do k = 1, map%n_special
         associate (p => map%special(k))
            if (p%kind == map_point_meet .and. any(p%codes == 101) .and. &
               any(p%codes == 103)) meet = abs(p%alpha/0.567_wp - 1.0_wp) < 1.0e-2_wp .and. &
               abs(p%mu/2.95_wp - 1.0_wp) < 1.0e-2_wp
            if (p%kind == map_point_turn .and. any(p%codes == 212) .and. &
               any(p%codes == 221)) turn = abs(p%alpha/0.8777_wp - 1.0_wp) < 1.0e-2_wp
         end associate
      end do
      call check(error, meet, "101 meets 103 at alpha 0.567, mu 2.95")
      call check(error, turn, "212 turns back into 221 near alpha 0.878")
      if (allocated(error)) return
      call check(error, index(special_meaning(map%special(1)), "pull-off") > 0 .or. &
         index(special_meaning(map%special(1)), "full contact") > 0, "meaning")
   end subroutine test_special

   subroutine test_invalid(error)
      type(error_type), allocatable, intent(out) :: error
      type(map_type) :: map
      integer :: status
      character(len=256) :: msg
      msg = ""
      call adhesion_map(model_jkr, [0.3_wp], 1.0e-3_wp, 1.0e3_wp, 10, map, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "model") > 0, &
         "jkr refused")
      call adhesion_map(model_dw, [0.3_wp, 0.1_wp], 1.0e-3_wp, 1.0e3_wp, 10, map, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "increasing") > 0, &
         "decreasing alpha refused")
      call adhesion_map(model_dw, [0.3_wp], 1.0_wp, 1.0_wp, 10, map, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "mu_lo") > 0, &
         "empty mu range refused")
      call adhesion_map(model_dw, [0.3_wp], 1.0e-3_wp, 1.0e3_wp, 1, map, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "n_mu") > 0, &
         "n_mu = 1 refused")
      call adhesion_map(model_dw, [0.0_wp], 1.0e-3_wp, 1.0e3_wp, 10, map, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "alpha") > 0, &
         "alpha = 0 refused")
      if (allocated(error)) return
      call adhesion_map(model_dw, [0.3_wp], 1.0e-3_wp, 1.0e3_wp, 10, map, status, msg, &
         control=4)
      call check(error, status == wa_invalid_argument .and. index(msg, "control") > 0, &
         "control = 4 refused")
      if (allocated(error)) return
      ! the grid's bounds, checked before it is allocated (issue 3)
      call adhesion_map(model_dw, [0.3_wp], 1.0e-3_wp, 1.0e3_wp, map_n_mu_max + 1, map, &
         status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "n_mu") > 0, &
         "n_mu = 100001 refused")
      if (allocated(error)) return
      call adhesion_map(model_dw, grid(map_n_alpha_max + 1), 1.0e-3_wp, 1.0e3_wp, 2, map, &
         status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "at most 100000") > 0, &
         "100001 alpha refused")
      if (allocated(error)) return
      call adhesion_map(model_dw, grid(map_n_alpha_max), 1.0e-3_wp, 1.0e3_wp, &
         map_cells_max/map_n_alpha_max + 1, map, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "1e7") > 0, &
         "more than 1e7 cells refused")
   end subroutine test_invalid

   !> n increasing alpha values from 0.01.
   pure function grid(n) result(alpha)
      integer, intent(in) :: n
      real(wp) :: alpha(n)
      integer :: i
      alpha = [(0.01_wp*(1.0_wp + 1.0e-4_wp*i), i = 1, n)]
   end function grid

   !> Gap control (codes 3xx, 4xx): DW, 20 alpha over [0.01, 10], every boundary point on
   !> the grid rebisected by gap_mechanism_change from +-1e-6 agrees to 1e-8 relative
   !> (the jump-out boundaries 401, 423 included: the jump-out counts from a maximum of
   !> gbar* at a* >= 1e-3, a smooth condition; doc/theory.md, "Adhesion map").
   subroutine test_dw_gap_points(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: alpha(20)
      integer :: j
      alpha = [(10.0_wp**(-2.0_wp + 3.0_wp*real(j - 1, wp)/19.0_wp), j = 1, 20)]
      call check_gap_points(error, model_dw, alpha, 1.0e-3_wp, 1.0e3_wp, 5, 20, 1)
   end subroutine test_dw_gap_points

   !> MD at alpha 0.3, 1, 3 (each scanned): the four to six gap boundaries there.
   subroutine test_md_gap_points(error)
      type(error_type), allocatable, intent(out) :: error
      call check_gap_points(error, model_md, [0.3_wp, 1.0_wp, 3.0_wp], 1.0e-2_wp, 1.0e2_wp, &
         1, 10, 4)
   end subroutine test_md_gap_points

   subroutine check_gap_points(error, model, alpha, mu_lo, mu_hi, every, min_points, &
         min_boundaries)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in) :: model, every, min_points, min_boundaries
      real(wp), intent(in) :: alpha(:), mu_lo, mu_hi
      type(map_type) :: map
      real(wp) :: mu_c, worst, d
      character(len=200) :: text
      integer :: status, c, p, n_checked
      character(len=256) :: msg
      msg = ""
      call adhesion_map(model, alpha, mu_lo, mu_hi, 40, map, status, msg, &
         scan_every=every, control=map_control_gap)
      call check(error, status == wa_ok, "map: "//trim(msg))
      if (allocated(error)) return
      call check(error, map%n_boundaries >= min_boundaries, "gap boundaries found")
      if (allocated(error)) return
      worst = 0.0_wp
      n_checked = 0
      do c = 1, map%n_boundaries
         associate (b => map%boundary(c))
            call check(error, b%which == 3 .or. b%which == 4, "only gap boundaries")
            if (allocated(error)) return
            do p = 1, b%n
               if (.not. any(alpha == b%alpha(p))) cycle
               call gap_mechanism_change(model, b%alpha(p), b%which, &
                  b%mu(p)*(1.0_wp - 1.0e-6_wp), b%mu(p)*(1.0_wp + 1.0e-6_wp), mu_c, status)
               write (text, '(a,i0,a,es24.16,a,es24.16,a,i0)') "gap_mechanism_change "// &
                  "converges: code ", b%code, " alpha ", b%alpha(p), " mu ", b%mu(p), &
                  " status ", status
               call check(error, status == wa_ok, trim(text))
               if (allocated(error)) return
               d = abs(mu_c - b%mu(p))/b%mu(p)
               worst = max(worst, d)
               n_checked = n_checked + 1
            end do
         end associate
      end do
      write (text, '(a,i0,a,es10.3)') "points checked: ", n_checked, ", worst ", worst
      write (*, '(4x,a)') "gap boundaries: "//trim(text)
      call check(error, n_checked >= min_points, trim(text))
      if (allocated(error)) return
      call check(error, worst <= 1.0e-8_wp, "gap boundary points agree with "// &
         "gap_mechanism_change: "//trim(text))
   end subroutine check_gap_points

   subroutine test_gap_codes(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, boundary_meaning(401) == "gap retraction: gradual -> jump-out", &
         "meaning of 401")
      if (allocated(error)) return
      call check(error, boundary_meaning(323) == "gap approach: gradual+inner jumps -> "// &
         "jump-in+inner jumps", "meaning of 323")
      if (allocated(error)) return
      call check(error, boundary_meaning(302) == "gap approach: gradual -> gradual+inner "// &
         "jumps", "meaning of 302")
      if (allocated(error)) return
      call check(error, boundary_meaning(344) == "unknown" .and. boundary_meaning(504) == &
         "unknown", "unknown gap codes")
      if (allocated(error)) return
      call check(error, gap_mechanism_name(4, 3) == "inner jumps+jump-out", "name")
   end subroutine test_gap_codes

   !> DW at alpha 0.1, 0.2, 3 under both controls: load regions as before, and the gap
   !> regions hold mech_below just under each gap boundary and mech_above just over it.
   subroutine test_gap_regions(error)
      type(error_type), allocatable, intent(out) :: error
      type(map_type) :: map
      integer :: status, c
      logical :: any_gap
      call adhesion_map(model_dw, [0.1_wp, 0.2_wp, 3.0_wp], 1.0e-3_wp, 1.0e3_wp, 40, map, &
         status, scan_every=2, control=map_control_both)
      call check(error, status == wa_ok, "map")
      if (allocated(error)) return
      call check(error, all(map%ga_region == 1), "DW approach: always jump-in")
      if (allocated(error)) return
      call check_regions(error, map)
      if (allocated(error)) return
      any_gap = any([(map%boundary(c)%which > 2, c = 1, map%n_boundaries)])
      call check(error, any_gap, "a gap boundary (401)")
   end subroutine test_gap_regions

end module test_map
