!> The adhesion map of the (alpha, mu) plane: every change of the full-contact mechanism
!> (gradual / jump from case 1 / jump from case 2 / snap at P* = 0) and of the pull-off
!> mechanism (gradual / jump from case 1 / jump from case 2) as a curve mu_b(alpha), each
!> point located to 2e-9 relative in mu, plus a region grid (the mechanisms in every cell).
!>
!> Method (doc/theory.md, "Adhesion map"): a coarse log scan in mu at every `scan_every`-th
!> alpha (and the first and last) finds the changes; each change is then continued over
!> the whole alpha grid in both directions: the next point is predicted by extrapolating
!> the last three or four in (ln alpha, ln mu), bracketed by two load paths, and refined by a
!> safeguarded secant on a smooth indicator whose zero is the change (the difference of
!> the two loads whose order decides the mechanism, e.g. the largest fold load minus the
!> load at a* -> 1/2), with a bisection step whenever the secant does not halve the
!> bracket. Every trial mu is classified by its own load path, so the result is a bracket
!> of the mechanism change, like `mechanism_change`'s. Where a curve cannot be continued
!> (it meets another boundary, a region closes, or it leaves [mu_lo, mu_hi]) its end is
!> located by bisection in alpha to 1e-6 relative.
module wa_map
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, wa_not_converged, set_error
   use wa_params, only: params_type, new_params, alpha_min, alpha_max, mu_min, mu_max
   use wa_state, only: model_dw, model_md, zone_inside
   use wa_branch, only: branch_type, trace_branch, trace_options, event_pull_off
   use wa_curve, only: curve_residual, curve_y_max
   use wa_loadpath, only: path_type, path_from_branch, mechanism_gradual, &
      mechanism_jump_case1, mechanism_jump_case2, mechanism_snap, a_point_pull_off
   use wa_gapmech, only: gap_mechanisms_from_branch, gap_mechanism_name
   implicit none
   private

   public :: map_type, map_boundary, adhesion_map, boundary_code, boundary_meaning
   public :: map_end_grid, map_end_inside, map_end_mu_range, map_end_failed
   public :: map_point, special_meaning, map_point_meet, map_point_turn, map_point_end, &
      map_point_fail
   public :: map_control_load, map_control_gap, map_control_both
   public :: map_n_mu_max, map_n_alpha_max, map_cells_max

   !> What the map locates (adhesion_map's `control`): the load-control boundaries (which 1
   !> full contact, 2 pull-off), the gap-control ones (which 3 approach, 4 retraction:
   !> wa_gapmech), or both
   integer, parameter :: map_control_load = 1, map_control_gap = 2, map_control_both = 3

   !> How a boundary curve starts or ends: at the first/last alpha of the grid; inside the
   !> grid (it meets another boundary, or the region it bounds closes: located to 1e-6
   !> relative in alpha); where it leaves [mu_lo, mu_hi]; where the load path fails.
   integer, parameter :: map_end_grid = 0, map_end_inside = 1, map_end_mu_range = 2, &
      map_end_failed = 3

   !> Relative width in mu of the final bracket of every boundary point
   real(wp), parameter :: tol_t = 2.0e-9_wp
   !> Relative accuracy in alpha of a located start or end of a curve
   real(wp), parameter :: tol_alpha = 1.0e-6_wp
   !> Bound on the curves of one map, and on those of load control (which 1, 2) and of gap
   !> control (3, 4) each: a tangle of one control does not crowd out the other
   integer, parameter :: max_boundaries = 128, max_per_control = 64
   !> Bounds on the grid (checked before anything is allocated): at most map_n_mu_max mu
   !> and map_n_alpha_max alpha values, at most map_cells_max cells n_mu*n_alpha (each
   !> cell holds four mechanism codes)
   integer, parameter :: map_n_mu_max = 100000, map_n_alpha_max = 100000, &
      map_cells_max = 10000000

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

   !> One load path reduced to what the map needs: both mechanisms and the loads whose
   !> order decides them (NaN where absent).
   type :: probe_type
      integer :: status = wa_ok
      !> Full contact, pull-off (load control), approach, retraction (gap control); -1
      !> where not computed
      integer :: mech(4) = -1
      !> Full contact: 0 P* at a* -> 1/2, 1/2 largest maximum on case 1 / case 2, 3 zero
      real(wp) :: v_fc(0:3) = 0.0_wp
      !> Pull-off: 0 P* at a* -> 0, 1/2 lowest minimum on case 1 / case 2
      real(wp) :: v_pf(0:2) = 0.0_wp
      !> F(a_start, y_max): changes sign where a case-1 root is born at the branch's
      !> first point (the corner minimum of case 2 appears: gradual <-> jump case 2)
      real(wp) :: f_start = 0.0_wp
      !> ln(a* of the pull-off / a_point_pull_off) where contact is lost at a minimum
      !> (gradual <-> jump where the minimum passes a_point_pull_off)
      real(wp) :: ln_a_pf = 0.0_wp
      !> ln(a* / a_point_pull_off) at the maximum of gbar* from which the gap-controlled
      !> retraction jumps out of contact (gradual <-> jump-out where it passes 1e-3)
      real(wp) :: ln_a_out = 0.0_wp
      !> gbar* where contact sets in minus gbar* of the approach's first jump from a state
      !> without contact (gradual contact <-> jump-in where the landing passes the onset)
      real(wp) :: g_in = 0.0_wp
      !> 1 - gbar* of the first approach / retraction jump between case 1 and c* = 1/2
      !> (inner jumps <-> none where its end on the c* = 1/2 sheet passes the onset of
      !> contact, gbar* = 1)
      real(wp) :: g_half(2) = 0.0_wp
   end type probe_type

   !> The indicators a boundary can be followed by (the first whose signs differ across
   !> a located bracket is used for the next point's secant)
   integer, parameter :: ind_none = 0, ind_loads = 1, ind_f_start = 2, ind_a_pf = 3, &
      ind_a_out = 4, ind_g_in = 5, ind_g_half = 6

   !> What continuing a curve needs (fixed for one map).
   type :: tracker_type
      integer :: model = 0, which = 0, ma = -1, mb = -1, control = map_control_load
      real(wp) :: t_min = 0.0_wp, t_max = 0.0_wp
      integer :: n_paths = 0
      !> d(indicator)/d(ln mu) at the last point located (0: not known): the first step
      !> of the secant that locates the next point
      real(wp) :: slope = 0.0_wp
      !> ind_* of the indicator that changed sign across the last located bracket
      integer :: ind = ind_loads
   end type tracker_type

contains

   !> The boundary code of a change of mechanism `which` (1 full contact, 2 pull-off)
   !> from mech_below to mech_above as mu grows.
   pure integer function boundary_code(which, mech_below, mech_above)
      integer, intent(in) :: which, mech_below, mech_above
      boundary_code = 100*which + 10*mech_below + mech_above
   end function boundary_code

   !> "full contact: gradual -> jump case 1" and the like, for a boundary code.
   pure function boundary_meaning(code) result(text)
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

   !> Build the map of `model` (model_dw or model_md) over the increasing grid alpha(:)
   !> and n_mu log-spaced mu in [mu_lo, mu_hi]. scan_every (default 20): the coarse mu scan
   !> that discovers boundaries runs at every scan_every-th alpha (and the last).
   !> control (default map_control_load): map_control_gap for the gap-control boundaries
   !> (approach, retraction: codes 3xx, 4xx) only, map_control_both for all.
   !> status: wa_invalid_argument for bad input (errmsg names it), else wa_ok; boundaries
   !> that cannot be continued end with end_kind = map_end_failed, never with a wrong point.
   subroutine adhesion_map(model, alpha, mu_lo, mu_hi, n_mu, map, status, errmsg, scan_every, &
         control)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha(:), mu_lo, mu_hi
      integer, intent(in) :: n_mu
      type(map_type), intent(out) :: map
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, intent(in), optional :: scan_every, control
      integer :: every, j, na

      call check_input(model, alpha, mu_lo, mu_hi, n_mu, status, errmsg)
      if (status /= wa_ok) return
      every = 20
      if (present(scan_every)) every = scan_every
      if (every < 1) then
         call set_error(wa_invalid_argument, "adhesion_map: scan_every must be >= 1", &
            status, errmsg)
         return
      end if
      map%control = map_control_load
      if (present(control)) map%control = control
      if (map%control < map_control_load .or. map%control > map_control_both) then
         call set_error(wa_invalid_argument, "adhesion_map: control must be 1 (load), "// &
            "2 (gap) or 3 (both)", status, errmsg)
         return
      end if
      na = size(alpha)
      map%model = model
      map%alpha = alpha
      map%mu = [(exp(log(mu_lo) + (log(mu_hi) - log(mu_lo))*real(j - 1, wp)/ &
         real(n_mu - 1, wp)), j = 1, n_mu)]
      allocate (map%fc_region(n_mu, na), map%pf_region(n_mu, na), map%boundary(0))
      allocate (map%ga_region(n_mu, na), map%gr_region(n_mu, na))
      map%fc_region = -1
      map%pf_region = -1
      map%ga_region = -1
      map%gr_region = -1
      do j = 1, na
         if (mod(j - 1, every) /= 0 .and. j /= na) cycle
         call scan_alpha(map, j)
      end do
      call fill_regions(map)
      call find_special_points(map)
   end subroutine adhesion_map

   !> "pull-off: jump case 1 -> jump case 2 turns back in alpha" and the like.
   pure function special_meaning(point) result(text)
      type(map_point), intent(in) :: point
      character(len=:), allocatable :: text
      select case (point%kind)
      case (map_point_meet)
         text = boundary_meaning(point%codes(1))//" meets "// &
            boundary_meaning(point%codes(2))
      case (map_point_turn)
         text = boundary_meaning(point%codes(1))//" turns back in alpha (meets its "// &
            "reverse "//code_text(point%codes(2))//"; the region between closes)"
      case (map_point_end)
         text = boundary_meaning(point%codes(1))//" ends (its region closes)"
      case (map_point_fail)
         text = boundary_meaning(point%codes(1))//": the load path fails here"
      case default
         text = "unknown"
      end select
   end function special_meaning

   pure function code_text(code) result(text)
      integer, intent(in) :: code
      character(len=:), allocatable :: text
      character(len=12) :: buf
      write (buf, '(i0)') code
      text = trim(buf)
   end function code_text

   !> Every curve end inside the grid (map_end_inside, map_end_failed) becomes a special
   !> point: a turn where it coincides with an end of the reverse curve, a meeting where it
   !> coincides with an end of, or lies on, another curve, else an end (or a failure).
   !> Coincide: within one grid step in ln alpha (at least 1e-3; a curve whose
   !> continuation fails short of its true end stops at the last grid point) and 0.1 in
   !> ln mu (near a turn mu varies like the square root of the distance in alpha). Each
   !> pair of coinciding ends gives one point (at the mean of the two in logs).
   pure subroutine find_special_points(map)
      type(map_type), intent(inout) :: map
      real(wp), parameter :: tol_m = 1.0e-1_wp
      real(wp) :: tol_a
      type(map_point) :: pt
      real(wp) :: a, m, a2, m2
      integer :: c, e, c2, e2, kind, kind2
      logical :: used(max_boundaries, 2), found
      allocate (map%special(0))
      used = .false.
      tol_a = 1.0e-3_wp
      if (size(map%alpha) > 1) tol_a = max(tol_a, 1.01_wp*maxval(log(map%alpha(2:)/ &
         map%alpha(:size(map%alpha) - 1))))
      do c = 1, map%n_boundaries
         do e = 1, 2
            if (used(c, e)) cycle
            call end_of(c, e, a, m, kind)
            if (kind /= map_end_inside .and. kind /= map_end_failed) cycle
            used(c, e) = .true.
            pt%alpha = a
            pt%mu = m
            pt%codes = [map%boundary(c)%code, 0]
            pt%kind = merge(map_point_fail, map_point_end, kind == map_end_failed)
            found = .false.
            do c2 = 1, map%n_boundaries              ! an end of another curve here
               if (c2 == c) cycle
               do e2 = 1, 2
                  if (used(c2, e2)) cycle
                  call end_of(c2, e2, a2, m2, kind2)
                  if (kind2 /= map_end_inside .and. kind2 /= map_end_failed) cycle
                  if (abs(log(a2/a)) > tol_a .or. abs(log(m2/m)) > tol_m) cycle
                  used(c2, e2) = .true.
                  pt%codes(2) = map%boundary(c2)%code
                  pt%kind = merge(map_point_turn, map_point_meet, &
                     reverse(map%boundary(c)%code) == map%boundary(c2)%code)
                  pt%alpha = sqrt(a*a2)
                  pt%mu = sqrt(m*m2)
                  found = .true.
                  exit
               end do
               if (found) exit
            end do
            if (.not. found) then                 ! on another curve
               do c2 = 1, map%n_boundaries
                  if (c2 == c) cycle
                  if (on_curve(map%boundary(c2), a, m)) then
                     pt%codes(2) = map%boundary(c2)%code
                     pt%kind = map_point_meet
                     exit
                  end if
               end do
            end if
            map%special = [map%special, pt]
            map%n_special = map%n_special + 1
         end do
      end do
   contains
      pure subroutine end_of(ci, ei, ae, me, ke)
         integer, intent(in) :: ci, ei
         real(wp), intent(out) :: ae, me
         integer, intent(out) :: ke
         associate (b => map%boundary(ci))
            if (ei == 1) then
               ae = b%alpha(1)
               me = b%mu(1)
               ke = b%start_kind
            else
               ae = b%alpha(b%n)
               me = b%mu(b%n)
               ke = b%end_kind
            end if
         end associate
      end subroutine end_of

      pure integer function reverse(code)
         integer, intent(in) :: code
         reverse = 100*(code/100) + 10*mod(code, 10) + mod(code/10, 10)
      end function reverse

      !> (a, m) within tol_a of the curve's alpha span and tol_m in ln mu of its polyline
      pure logical function on_curve(b, a, m)
         type(map_boundary), intent(in) :: b
         real(wp), intent(in) :: a, m
         real(wp) :: f, mi
         integer :: i
         on_curve = .false.
         do i = 1, b%n - 1
            if (.not. (a >= b%alpha(i)*(1.0_wp - tol_a) .and. &
               a <= b%alpha(i + 1)*(1.0_wp + tol_a))) cycle
            f = 0.0_wp
            if (b%alpha(i + 1) > b%alpha(i)) f = min(1.0_wp, max(0.0_wp, &
               log(a/b%alpha(i))/log(b%alpha(i + 1)/b%alpha(i))))
            mi = exp(log(b%mu(i)) + f*log(b%mu(i + 1)/b%mu(i)))
            if (abs(log(m/mi)) <= tol_m) then
               on_curve = .true.
               return
            end if
         end do
      end function on_curve
   end subroutine find_special_points

   subroutine check_input(model, alpha, mu_lo, mu_hi, n_mu, status, errmsg)
      integer, intent(in) :: model, n_mu
      real(wp), intent(in) :: alpha(:), mu_lo, mu_hi
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer :: j
      status = wa_ok
      if (model /= model_dw .and. model /= model_md) then
         call set_error(wa_invalid_argument, "adhesion_map: model must be dw (2) or md (3)", &
            status, errmsg)
      else if (size(alpha) < 1) then
         call set_error(wa_invalid_argument, "adhesion_map: alpha must hold at least one "// &
            "value", status, errmsg)
      else if (.not. all(alpha >= alpha_min .and. alpha <= alpha_max)) then
         call set_error(wa_invalid_argument, "adhesion_map: every alpha must be in "// &
            "[1e-12, 1e12]", status, errmsg)
      else if (.not. (mu_lo >= mu_min .and. mu_hi <= mu_max .and. mu_lo < mu_hi)) then
         call set_error(wa_invalid_argument, "adhesion_map: mu_lo < mu_hi required, both "// &
            "in [1e-100, 1e100]", status, errmsg)
      else if (n_mu < 2 .or. n_mu > map_n_mu_max) then
         call set_error(wa_invalid_argument, "adhesion_map: n_mu must be in [2, 100000]", &
            status, errmsg)
      else if (size(alpha) > map_n_alpha_max) then
         call set_error(wa_invalid_argument, "adhesion_map: alpha must hold at most 100000 "// &
            "values", status, errmsg)
      else if (real(n_mu, wp)*real(size(alpha), wp) > real(map_cells_max, wp)) then
         call set_error(wa_invalid_argument, "adhesion_map: n_mu times the number of alpha "// &
            "values must be at most 1e7 (the region grid's cells)", status, errmsg)
      else
         do j = 2, size(alpha)
            if (.not. alpha(j) > alpha(j - 1)) then
               call set_error(wa_invalid_argument, "adhesion_map: alpha must be strictly "// &
                  "increasing", status, errmsg)
               return
            end if
         end do
      end if
   end subroutine check_input

   !> Coarse scan at alpha(j): the mechanisms on the mu grid; every change between two
   !> neighbouring successful rows not on a curve already found starts a new curve.
   subroutine scan_alpha(map, j)
      type(map_type), intent(inout) :: map
      integer, intent(in) :: j
      type(probe_type) :: pr
      integer :: i, nm
      integer, allocatable :: mech(:, :)
      nm = size(map%mu)
      allocate (mech(4, nm))
      do i = 1, nm
         call probe(map%model, map%alpha(j), log(map%mu(i)), pr, map%control)
         map%n_paths = map%n_paths + 1
         mech(:, i) = pr%mech
      end do
      map%fc_region(:, j) = mech(1, :)
      map%pf_region(:, j) = mech(2, :)
      map%ga_region(:, j) = mech(3, :)
      map%gr_region(:, j) = mech(4, :)
      call start_curves(map, j, log(map%mu), mech)
   end subroutine scan_alpha

   !> Every change between neighbouring successful rows of mech (at ln mu = t, alpha(j))
   !> that no curve found so far explains starts a new curve.
   recursive subroutine start_curves(map, j, t, mech)
      type(map_type), intent(inout) :: map
      integer, intent(in) :: j
      real(wp), intent(in) :: t(:)
      integer, intent(in) :: mech(:, :)
      integer :: i, k, which, c
      i = first_good(maxval(mech, dim=1), 0)
      do while (i > 0)
         k = first_good(maxval(mech, dim=1), i)
         if (k == 0) exit
         do which = 1, 4
            if (mech(which, i) == mech(which, k)) cycle
            if (mech(which, i) < 0 .or. mech(which, k) < 0) cycle
            if (known(map, j, which, mech(which, i), mech(which, k), exp(t(i)), exp(t(k)))) cycle
            if (map%n_boundaries >= max_boundaries) return
            if (count([(map%boundary(c)%which > 2 .eqv. which > 2, c=1, map%n_boundaries)]) &
               >= max_per_control) cycle
            call new_curve(map, j, which, mech(which, i), mech(which, k), t(i), t(k))
         end do
         i = k
      end do
   end subroutine start_curves

   !> A finer scan of ln mu in [t_c - w, t_c + w] (and inside the map's mu range) at
   !> alpha(j), where a curve ended: finds the curves it turns into or meets there.
   recursive subroutine local_scan(map, j, t_c, w, control)
      type(map_type), intent(inout) :: map
      integer, intent(in) :: j
      real(wp), intent(in) :: t_c, w
      !> map_control_load or map_control_gap: the control of the curve that ended (the
      !> curves it turns into or meets are of the same control)
      integer, intent(in) :: control
      integer, parameter :: n = 24
      type(probe_type) :: pr
      real(wp) :: t(n), lo, hi
      integer :: mech(4, n), i
      lo = max(t_c - w, log(map%mu(1)))
      hi = min(t_c + w, log(map%mu(size(map%mu))))
      if (.not. hi > lo) return
      do i = 1, n
         t(i) = lo + (hi - lo)*real(i - 1, wp)/real(n - 1, wp)
         call probe(map%model, map%alpha(j), t(i), pr, control)
         mech(:, i) = pr%mech
      end do
      map%n_paths = map%n_paths + n
      call start_curves(map, j, t, mech)
   end subroutine local_scan

   pure integer function first_good(mech, i)
      integer, intent(in) :: mech(:), i
      integer :: r
      first_good = 0
      do r = i + 1, size(mech)
         if (mech(r) >= 0) then
            first_good = r
            return
         end if
      end do
   end function first_good

   !> A curve of this kind (or its reverse) passes alpha(j) between mu_a and mu_b already,
   !> or within 3e-3 relative of them: a mechanism that flickers near a boundary (201 does,
   !> over 1e-5 to 1e-3 relative) must not start a second copy of the curve.
   pure logical function known(map, j, which, ma, mb, mu_a, mu_b)
      type(map_type), intent(in) :: map
      integer, intent(in) :: j, which, ma, mb
      real(wp), intent(in) :: mu_a, mu_b
      real(wp), parameter :: band = 3.0e-3_wp
      integer :: c, p
      known = .false.
      do c = 1, map%n_boundaries
         associate (b => map%boundary(c))
            if (b%code /= boundary_code(which, ma, mb) .and. &
               b%code /= boundary_code(which, mb, ma)) cycle
            do p = 1, b%n
               if (b%alpha(p) /= map%alpha(j)) cycle
               if (b%mu(p) >= mu_a*(1.0_wp - band) .and. b%mu(p) <= mu_b*(1.0_wp + band)) then
                  known = .true.
                  return
               end if
            end do
         end associate
      end do
   end function known

   !> Locate a change bracketed by the scan at alpha(j), then continue it both ways.
   recursive subroutine new_curve(map, j, which, ma, mb, t_a, t_b)
      type(map_type), intent(inout) :: map
      integer, intent(in) :: j, which, ma, mb
      real(wp), intent(in) :: t_a, t_b
      type(tracker_type) :: tr
      type(probe_type) :: pa, pb
      type(map_boundary) :: fwd, bwd, curve
      real(wp) :: t, slope0
      integer :: stat, m_hi, k_fwd, k_bwd

      tr%model = map%model
      ! a curve's probes need only its own control's mechanisms (a load-control curve's
      ! traces then skip the mean gap even in a map of both)
      tr%control = merge(map_control_load, map_control_gap, which <= 2)
      tr%which = which
      tr%ma = ma
      tr%mb = mb
      tr%t_min = log(map%mu(1))
      tr%t_max = log(map%mu(size(map%mu)))
      call probe(map%model, map%alpha(j), t_a, pa, map%control)
      call probe(map%model, map%alpha(j), t_b, pb, map%control)
      tr%n_paths = 2
      call refine(tr, map%alpha(j), t_a, pa, t_b, pb, t, m_hi, stat)
      if (stat /= wa_ok .or. m_hi /= mb) then        ! a third mechanism inside: skip
         map%n_paths = map%n_paths + tr%n_paths
         return
      end if
      slope0 = tr%slope
      call continue_curve(tr, map%alpha, j, t, +1, fwd, k_fwd)
      tr%slope = slope0
      call continue_curve(tr, map%alpha, j, t, -1, bwd, k_bwd)
      map%n_paths = map%n_paths + tr%n_paths
      curve%which = which
      curve%mech_below = ma
      curve%mech_above = mb
      curve%code = boundary_code(which, ma, mb)
      curve%n = bwd%n + fwd%n - 1
      curve%alpha = [bwd%alpha(bwd%n:1:-1), fwd%alpha(2:fwd%n)]
      curve%mu = [bwd%mu(bwd%n:1:-1), fwd%mu(2:fwd%n)]
      curve%start_kind = bwd%end_kind
      curve%end_kind = fwd%end_kind
      if (duplicate(map, curve)) return
      map%boundary = [map%boundary, curve]
      map%n_boundaries = map%n_boundaries + 1
      if (fwd%end_kind == map_end_inside) call scan_near_end(k_fwd, +1, fwd)
      if (bwd%end_kind == map_end_inside) call scan_near_end(k_bwd, -1, bwd)
   contains
      !> The curves this one turns into or meets: scans around it at the last grid alpha
      !> it passes, the next one, and one grid step back (where a partner curve that turns
      !> with it at the end has moved away from it; 2 and 4 steps back as well found no
      !> other curve on the benchmark grids and cost 7 % of the DW map).
      recursive subroutine scan_near_end(k, dir, piece)
         integer, intent(in) :: k, dir
         type(map_boundary), intent(in) :: piece
         real(wp) :: t_end, w
         integer :: i, m, kk
         t_end = log(piece%mu(piece%n))
         if (k + dir >= 1 .and. k + dir <= size(map%alpha)) &
            call local_scan(map, k + dir, t_end, 0.25_wp, tr%control)
         do m = 0, 1
            kk = k - dir*m
            if (kk < 1 .or. kk > size(map%alpha)) exit
            do i = 1, piece%n
               if (piece%alpha(i) /= map%alpha(kk)) cycle
               w = max(0.02_wp, 3.0_wp*abs(log(piece%mu(i)) - t_end))
               call local_scan(map, kk, log(piece%mu(i)), w, tr%control)
            end do
         end do
      end subroutine scan_near_end
   end subroutine new_curve

   !> The curve repeats one found already: same code, within 3e-3 relative in mu at three
   !> or more common alpha (a copy started inside a flickering band).
   pure logical function duplicate(map, curve)
      type(map_type), intent(in) :: map
      type(map_boundary), intent(in) :: curve
      integer :: c, p, q, n_same
      duplicate = .false.
      do c = 1, map%n_boundaries
         if (map%boundary(c)%code /= curve%code) cycle
         n_same = 0
         do p = 1, curve%n
            do q = 1, map%boundary(c)%n
               if (map%boundary(c)%alpha(q) /= curve%alpha(p)) cycle
               if (abs(map%boundary(c)%mu(q) - curve%mu(p)) <= 3.0e-3_wp*curve%mu(p)) &
                  n_same = n_same + 1
            end do
         end do
         duplicate = n_same >= min(3, curve%n)
         if (duplicate) return
      end do
   end function duplicate

   !> Continue the curve through (alpha(j), exp(t0)) over the grid in direction dir; the
   !> points come out in the order visited (the start point first). Steps in ln alpha
   !> adapt: a failed step is halved (the point in between, refined, joins the curve),
   !> down to tol_alpha, where the curve ends.
   subroutine continue_curve(tr, alpha, j, t0, dir, curve, k_last)
      type(tracker_type), intent(inout) :: tr
      real(wp), intent(in) :: alpha(:), t0
      integer, intent(in) :: j, dir
      type(map_boundary), intent(out) :: curve
      !> The last grid index the curve passes
      integer, intent(out) :: k_last
      integer, parameter :: max_points = 4096
      real(wp) :: x(max_points), y(max_points), a(max_points)
      real(wp) :: t, err, pred, h, xt, delta, preds(2:3), errs(2:3)
      integer :: order
      integer :: n, k, kind, iter, k_failed
      logical :: on_grid, approaching, refined(max_points)

      n = 1
      x(1) = log(alpha(j))
      a(1) = alpha(j)
      y(1) = t0
      refined(1) = .true.
      err = 1.0e-3_wp
      h = 0.01_wp
      approaching = .false.
      curve%end_kind = map_end_grid
      k = j + dir
      k_last = j
      k_failed = 0
      order = 2
      do iter = 1, 100000
         if (k < 1 .or. k > size(alpha) .or. n == max_points) exit
         xt = log(alpha(k))
         on_grid = abs(xt - x(n)) <= h
         if (.not. on_grid) xt = x(n) + dir*h
         ! quadratic or cubic in (ln alpha, ln mu), whichever predicted the last point better
         preds = [extrapolate(x, y, n, xt, 2), extrapolate(x, y, n, xt, 3)]
         pred = preds(order)
         delta = max(4.0_wp*err, 5.0_wp*tol_t)
         if (n < 3) delta = 1.0e-3_wp
         ! off the grid after a failed step only whether the curve is there matters
         call locate(tr, exp(xt), pred, delta, t, kind, &
            bracket_only=approaching .and. .not. on_grid)
         if (kind /= -1) then
            h = 0.5_wp*min(h, abs(xt - x(n)))
            curve%end_kind = kind
            approaching = .true.
            if (h < tol_alpha*max(1.0_wp, abs(x(n)))) exit
            ! the path fails again at this grid alpha (MD: the trace fails within ~2e-7 in
            ! mu of a reconnection of the case-1 curve): the curve ends here, rather than
            ! after every halving of the step has retried it (~50 paths each)
            if (kind == map_end_failed .and. on_grid) then
               if (k == k_failed) exit
               k_failed = k
            end if
            cycle
         end if
         curve%end_kind = map_end_grid
         n = n + 1
         x(n) = xt
         a(n) = merge(alpha(k), exp(xt), on_grid)
         y(n) = t
         refined(n) = .not. (approaching .and. .not. on_grid)
         if (n >= 4 .and. refined(n)) then
            errs = abs(t - preds)
            order = merge(3, 2, errs(3) < errs(2))
            err = errs(order)
         end if
         h = 2.0_wp*h
         if (on_grid) then
            k_last = k
            k = k + dir
            approaching = .false.
         end if
      end do
      if (.not. refined(n)) then            ! the last point found before the end, refined
         call locate(tr, exp(x(n)), y(n), 1.0e-3_wp, t, kind)
         if (kind == -1) then
            y(n) = t
            refined(n) = .true.
         end if
      end if
      curve%n = count(refined(1:n))
      curve%alpha = pack(a(1:n), refined(1:n))
      curve%mu = exp(pack(y(1:n), refined(1:n)))
   end subroutine continue_curve

   !> ln mu at x = ln alpha from the last (up to) degree + 1 points: a polynomial of that
   !> degree (Neville).
   pure real(wp) function extrapolate(x, y, n, xq, degree)
      real(wp), intent(in) :: x(:), y(:), xq
      integer, intent(in) :: n, degree
      real(wp) :: p(4)
      integer :: m, i, k, lo
      m = min(n, degree + 1, 4)
      lo = n - m
      p(1:m) = y(lo + 1:n)
      do k = 1, m - 1
         do i = 1, m - k
            p(i) = ((xq - x(lo + i + k))*p(i) + (x(lo + i) - xq)*p(i + 1)) &
               /(x(lo + i) - x(lo + i + k))
         end do
      end do
      extrapolate = p(1)
   end function extrapolate

   !> The change of the tracker's kind near ln mu = t_pred at alpha: bracket it with
   !> steps growing from delta (x4 each), then refine. kind = -1 when found (t), else
   !> the map_end_* reason it is not there.
   subroutine locate(tr, alpha, t_pred, delta, t, kind, bracket_only)
      type(tracker_type), intent(inout) :: tr
      real(wp), intent(in) :: alpha, t_pred, delta
      real(wp), intent(out) :: t
      integer, intent(out) :: kind
      !> Only bracket the change (t = the bracket's middle): enough to know it is there
      logical, intent(in), optional :: bracket_only
      type(probe_type) :: p0, p1
      real(wp) :: t0, t1, d, tol
      integer :: dir, m0, stat, m_hi, tries

      t = t_pred
      kind = map_end_inside
      if (t_pred < tr%t_min .or. t_pred > tr%t_max) then
         kind = map_end_mu_range
         return
      end if
      if (tr%slope /= 0.0_wp .and. .not. optval(bracket_only)) then
         call secant_point(tr, alpha, t_pred, max(64.0_wp*delta, 4.0e-3_wp), t, kind)
         if (kind == -1) then
            if (t < tr%t_min .or. t > tr%t_max) kind = map_end_mu_range
            return
         end if
         t = t_pred
         kind = map_end_inside
      end if
      t0 = t_pred
      call probe_near(tr, alpha, t0, p0)
      if (p0%status /= wa_ok) then
         kind = map_end_failed
         return
      end if
      m0 = p0%mech(tr%which)
      if (m0 /= tr%ma .and. m0 /= tr%mb) return
      dir = merge(1, -1, m0 == tr%ma)
      d = delta
      do tries = 1, 12
         t1 = t0 + dir*d
         call probe_near(tr, alpha, t1, p1)
         if (p1%status /= wa_ok) then
            kind = map_end_failed
            return
         end if
         if (p1%mech(tr%which) /= m0) exit
         t0 = t1
         p0 = p1
         d = 4.0_wp*d
         if (abs(t1 - t_pred) > max(64.0_wp*delta, 4.0e-3_wp)) return
      end do
      if (p1%mech(tr%which) == m0) return
      if (p1%mech(tr%which) /= merge(tr%mb, tr%ma, dir == 1)) return
      if (optval(bracket_only)) then      ! enough to know the curve is there (and not
         t = 0.5_wp*(t0 + t1)             ! another change of the same pair, farther off)
         if (abs(t - t_pred) > 5.0e-2_wp) return
         kind = -1
         if (t < tr%t_min .or. t > tr%t_max) kind = map_end_mu_range
         return
      end if
      tol = tol_t
      if (dir == 1) then
         call refine(tr, alpha, t0, p0, t1, p1, t, m_hi, stat, tol)
      else
         call refine(tr, alpha, t1, p1, t0, p0, t, m_hi, stat, tol)
      end if
      if (stat /= wa_ok) then
         kind = map_end_failed
      else if (m_hi == tr%mb) then
         kind = -1
         if (t < tr%t_min .or. t > tr%t_max) kind = map_end_mu_range
      end if
   end subroutine locate

   !> Probe at t; where the path fails there (the gap-controlled cycle can fail at isolated
   !> mu next to a change), at t +- 1e-6, 4e-6, 1.6e-5 instead (t returns the one used).
   subroutine probe_near(tr, alpha, t, p)
      type(tracker_type), intent(inout) :: tr
      real(wp), intent(in) :: alpha
      real(wp), intent(inout) :: t
      type(probe_type), intent(out) :: p
      real(wp), parameter :: offsets(7) = [0.0_wp, 1.0e-6_wp, -1.0e-6_wp, 4.0e-6_wp, &
         -4.0e-6_wp, 1.6e-5_wp, -1.6e-5_wp]
      integer :: k
      do k = 1, size(offsets)
         call probe(tr%model, alpha, t + offsets(k), p, tr%control)
         tr%n_paths = tr%n_paths + 1
         if (p%status == wa_ok) then
            t = t + offsets(k)
            return
         end if
         if (tr%control == map_control_load) return     ! the load path: no retries
      end do
   end subroutine probe_near

   pure logical function optval(flag)
      logical, intent(in), optional :: flag
      optval = .false.
      if (present(flag)) optval = flag
   end function optval

   !> The change near t_pred located from the indicator alone, with the slope of the
   !> last point as the first (Newton) step, then secant steps; once a step is below
   !> 1e-6 the bracket is closed by probes 0.45 tol_t either side of the estimate.
   !> Every probe must classify as tr%ma below the change and tr%mb above it. kind = -1
   !> when located (t, with a bracket <= tol_t), else map_end_inside: the caller falls
   !> back to bracketing and refine (the curve ends, flickers, or the indicator fails).
   subroutine secant_point(tr, alpha, t_pred, reach, t, kind)
      type(tracker_type), intent(inout) :: tr
      real(wp), intent(in) :: alpha, t_pred, reach
      real(wp), intent(out) :: t
      integer, intent(out) :: kind
      integer, parameter :: max_probes = 10
      type(probe_type) :: px, ps(max_probes)
      real(wp) :: t_lo, t_hi, hx(2), hg(2), r, x, g, slope, ts(max_probes)
      logical :: have_lo, have_hi, missing
      integer :: n_probes, nh, side, i_lo, i_hi

      kind = map_end_inside
      t = t_pred
      if (tr%ind == ind_none) return
      i_lo = 0
      i_hi = 0
      have_lo = .false.
      have_hi = .false.
      missing = .false.
      t_lo = 0.0_wp
      t_hi = 0.0_wp
      nh = 0
      hx = 0.0_wp
      hg = 0.0_wp
      n_probes = 0
      x = t_pred
      if (.not. sample(x)) return
      do while (n_probes < max_probes)
         if (have_lo .and. have_hi) then
            if (t_hi - t_lo <= tol_t) exit
         end if
         slope = tr%slope
         if (nh == 2) then
            if (hx(2) /= hx(1)) slope = (hg(2) - hg(1))/(hx(2) - hx(1))
         end if
         if (.not. (slope /= 0.0_wp .and. ieee_is_finite(slope))) return
         r = hx(2) - hg(2)/slope
         if (abs(r - t_pred) > reach) return
         if (have_lo .and. have_hi) then        ! keep inside the bracket
            if (.not. (r > t_lo .and. r < t_hi) .or. missing) r = 0.5_wp*(t_lo + t_hi)
         else if (missing) then
            return
         end if
         if (abs(r - hx(2)) > 1.0e-6_wp) then
            if (.not. sample(r)) return
            cycle
         end if
         ! close the bracket around r (keep an end already within tol_t/2 of it)
         side = 0
         if (have_lo) then
            if (r - t_lo < 0.5_wp*tol_t .and. r > t_lo) side = -1
         end if
         if (side /= -1) then
            if (.not. sample(r - 0.45_wp*tol_t)) return
         end if
         side = 0
         if (have_hi) then
            if (t_hi - r < 0.5_wp*tol_t .and. t_hi > r) side = 1
         end if
         if (side /= 1) then
            if (.not. sample(r + 0.45_wp*tol_t)) return
         end if
      end do
      if (.not. (have_lo .and. have_hi)) return
      if (.not. (t_hi - t_lo <= tol_t)) return
      t = 0.5_wp*(t_lo + t_hi)
      kind = -1
      call learn(tr, ts(1:n_probes), ps(1:n_probes), i_lo, i_hi, t)
   contains
      !> Probe at xs: false when the load path fails, the indicator is missing, the
      !> mechanism is neither of the pair, or the order contradicts the bracket.
      logical function sample(xs)
         real(wp), intent(in) :: xs
         sample = .false.
         call probe(tr%model, alpha, xs, px, tr%control)
         tr%n_paths = tr%n_paths + 1
         n_probes = n_probes + 1
         ts(n_probes) = xs
         ps(n_probes) = px
         if (px%status /= wa_ok) return
         g = indicator(tr, px)
         missing = .not. ieee_is_finite(g)    ! bracket only (bisect), unless nothing else
         if (missing .and. nh == 0) return
         if (px%mech(tr%which) == tr%ma) then
            if (have_hi) then
               if (xs >= t_hi) return
            end if
            if (.not. have_lo .or. xs > t_lo) then
               t_lo = xs
               i_lo = n_probes
            end if
            have_lo = .true.
         else if (px%mech(tr%which) == tr%mb) then
            if (have_lo) then
               if (xs <= t_lo) return
            end if
            if (.not. have_hi .or. xs < t_hi) then
               t_hi = xs
               i_hi = n_probes
            end if
            have_hi = .true.
         else
            return
         end if
         if (.not. missing) then
            hx = [hx(2), xs]
            hg = [hg(2), g]
            nh = min(nh + 1, 2)
         end if
         sample = .true.
      end function sample
   end subroutine secant_point

   !> Shrink [t_lo, t_hi] (mechanisms tr%ma at t_lo, other at t_hi) to tol_t: secant on
   !> the indicator of the tracker's pair, bisection whenever two steps do not halve the
   !> bracket or the indicator is missing. t = the midpoint; m_hi = mechanism at t_hi.
   subroutine refine(tr, alpha, t_lo_in, p_lo, t_hi_in, p_hi, t, m_hi, status, tol_in)
      type(tracker_type), intent(inout) :: tr
      real(wp), intent(in) :: alpha, t_lo_in, t_hi_in
      !> Width of the final bracket (default tol_t)
      real(wp), intent(in), optional :: tol_in
      type(probe_type), intent(in) :: p_lo, p_hi
      real(wp), intent(out) :: t
      integer, intent(out) :: m_hi, status
      !> Where a trial point fails, others of the bracket (the gap-controlled cycle can fail
      !> at isolated mu next to a change: wa_gappath's point solves at a gbar* pair's birth)
      real(wp), parameter :: fallback(15) = [0.5_wp, 0.25_wp, 0.75_wp, 0.125_wp, 0.875_wp, &
         0.0625_wp, 0.375_wp, 0.625_wp, 0.9375_wp, 0.3125_wp, 0.6875_wp, 0.1875_wp, &
         0.8125_wp, 0.4375_wp, 0.5625_wp]
      integer, parameter :: max_hist = 64
      type(probe_type) :: px, ps(max_hist)
      real(wp) :: t_lo, t_hi, hx(2), hg(2), x, g, w_old(2), ts(max_hist)
      integer :: nh, it, k, n, i_lo, i_hi
      logical :: bisect
      real(wp) :: tol

      tol = tol_t
      if (present(tol_in)) tol = tol_in
      t_lo = t_lo_in
      t_hi = t_hi_in
      m_hi = p_hi%mech(tr%which)
      status = wa_ok
      nh = 0
      n = 2
      ts(1:2) = [t_lo, t_hi]
      ps(1) = p_lo
      ps(2) = p_hi
      i_lo = 1
      i_hi = 2
      call choose_indicator(tr, p_lo, p_hi)
      call remember(t_lo, indicator(tr, p_lo))
      call remember(t_hi, indicator(tr, p_hi))
      w_old = huge(1.0_wp)
      do it = 1, 200
         if (t_hi - t_lo <= tol) exit
         bisect = nh < 2 .or. t_hi - t_lo > 0.5_wp*w_old(1)
         x = 0.5_wp*(t_lo + t_hi)
         if (.not. bisect) then
            if (hg(2) /= hg(1)) x = hx(2) - hg(2)*(hx(2) - hx(1))/(hg(2) - hg(1))
            if (.not. (x > t_lo .and. x < t_hi)) x = 0.5_wp*(t_lo + t_hi)
         end if
         x = min(max(x, t_lo + 0.45_wp*tol), t_hi - 0.45_wp*tol)
         do k = 1, size(fallback)
            call probe(tr%model, alpha, x, px, tr%control)
            tr%n_paths = tr%n_paths + 1
            if (px%status == wa_ok) exit
            x = t_lo + fallback(k)*(t_hi - t_lo)
         end do
         if (px%status /= wa_ok) then
            status = wa_not_converged
            exit
         end if
         w_old = [w_old(2), t_hi - t_lo]
         if (n < max_hist) then
            n = n + 1
            ts(n) = x
            ps(n) = px
         end if
         if (px%mech(tr%which) == tr%ma) then
            t_lo = x
            i_lo = n
         else
            t_hi = x
            i_hi = n
            m_hi = px%mech(tr%which)
         end if
         g = indicator(tr, px)
         call remember(x, g)
      end do
      if (status == wa_ok .and. t_hi - t_lo > tol) status = wa_not_converged
      t = 0.5_wp*(t_lo + t_hi)
      if (status == wa_ok .and. ts(i_lo) == t_lo .and. ts(i_hi) == t_hi .and. tol == tol_t) &
         call learn(tr, ts(1:n), ps(1:n), i_lo, i_hi, t)
   contains
      subroutine remember(tx, gx)
         real(wp), intent(in) :: tx, gx
         if (.not. ieee_is_finite(gx)) return
         hx = [hx(2), tx]
         hg = [hg(2), gx]
         nh = min(nh + 1, 2)
      end subroutine remember
   end subroutine refine

   !> The indicator of kind tr%ind at p (NaN where missing).
   pure real(wp) function indicator(tr, p)
      type(tracker_type), intent(in) :: tr
      type(probe_type), intent(in) :: p
      indicator = indicator_of(tr, tr%ind, p)
   end function indicator

   pure real(wp) function indicator_of(tr, ind, p)
      type(tracker_type), intent(in) :: tr
      integer, intent(in) :: ind
      type(probe_type), intent(in) :: p
      select case (ind)
      case (ind_loads)
         indicator_of = load_indicator(tr, p)
      case (ind_f_start)
         indicator_of = p%f_start
      case (ind_a_pf)
         indicator_of = p%ln_a_pf
         if (tr%which /= 2) indicator_of = ieee_value(1.0_wp, ieee_quiet_nan)
      case (ind_a_out)
         indicator_of = p%ln_a_out
         if (tr%which /= 4) indicator_of = ieee_value(1.0_wp, ieee_quiet_nan)
      case (ind_g_in)
         indicator_of = p%g_in
         if (tr%which /= 3) indicator_of = ieee_value(1.0_wp, ieee_quiet_nan)
      case (ind_g_half)
         indicator_of = ieee_value(1.0_wp, ieee_quiet_nan)
         if (tr%which == 3 .or. tr%which == 4) indicator_of = p%g_half(tr%which - 2)
      case default
         indicator_of = ieee_value(1.0_wp, ieee_quiet_nan)
      end select
   end function indicator_of

   !> tr%ind = the first indicator whose signs differ at the bracket ends p_lo, p_hi
   !> (ind_none if none does).
   pure subroutine choose_indicator(tr, p_lo, p_hi)
      type(tracker_type), intent(inout) :: tr
      type(probe_type), intent(in) :: p_lo, p_hi
      real(wp) :: g_lo, g_hi
      integer :: ind
      do ind = ind_loads, ind_g_half
         g_lo = indicator_of(tr, ind, p_lo)
         g_hi = indicator_of(tr, ind, p_hi)
         if (ieee_is_finite(g_lo) .and. ieee_is_finite(g_hi) .and. &
            ((g_lo <= 0.0_wp .and. g_hi >= 0.0_wp) .or. (g_lo >= 0.0_wp .and. g_hi <= 0.0_wp)) &
            .and. g_lo /= g_hi) then
            tr%ind = ind
            return
         end if
      end do
      tr%ind = ind_none
   end subroutine choose_indicator

   !> After a point is located at t (bracket ends ts(i_lo), ts(i_hi)): the indicator
   !> that changes sign across the bracket, and its slope in ln mu from the two probes
   !> nearest t at least 1e-7 apart (else the bracket ends): the next point's first step.
   pure subroutine learn(tr, ts, ps, i_lo, i_hi, t)
      type(tracker_type), intent(inout) :: tr
      real(wp), intent(in) :: ts(:), t
      type(probe_type), intent(in) :: ps(:)
      integer, intent(in) :: i_lo, i_hi
      real(wp) :: g(size(ts)), best, d, slope
      integer :: i, k, bi, bk
      call choose_indicator(tr, ps(i_lo), ps(i_hi))
      tr%slope = 0.0_wp
      if (tr%ind == ind_none) return
      do i = 1, size(ts)
         g(i) = indicator(tr, ps(i))
      end do
      bi = i_lo
      bk = i_hi
      best = huge(1.0_wp)
      do i = 1, size(ts)
         do k = i + 1, size(ts)
            if (.not. (ieee_is_finite(g(i)) .and. ieee_is_finite(g(k)))) cycle
            if (abs(ts(i) - ts(k)) < 1.0e-7_wp) cycle
            d = max(abs(ts(i) - t), abs(ts(k) - t))
            if (d < best) then
               best = d
               bi = i
               bk = k
            end if
         end do
      end do
      if (ts(bi) == ts(bk)) return
      slope = (g(bk) - g(bi))/(ts(bk) - ts(bi))
      if (ieee_is_finite(slope)) tr%slope = slope
   end subroutine learn

   !> The smooth quantity that vanishes where the tracker's mechanisms change (NaN when
   !> this load path lacks one of the loads): for full contact the larger of the competing
   !> maximum loads minus the other (against a snap: the largest load of the curve, whose
   !> sign decides whether the curve crosses P* = 0); for pull-off the difference of the
   !> competing minimum loads (gradual: P* at a* -> 0).
   pure real(wp) function load_indicator(tr, p)
      type(tracker_type), intent(in) :: tr
      type(probe_type), intent(in) :: p
      integer :: k
      if (tr%which > 2) then                ! gap control: no loads decide it
         load_indicator = ieee_value(1.0_wp, ieee_quiet_nan)
      else if (tr%which == 1) then
         if (tr%ma == mechanism_snap .or. tr%mb == mechanism_snap) then
            load_indicator = -huge(1.0_wp)
            do k = 0, 2
               if (ieee_is_finite(p%v_fc(k))) load_indicator = max(load_indicator, p%v_fc(k))
            end do
         else
            load_indicator = p%v_fc(tr%ma) - p%v_fc(tr%mb)
         end if
      else
         load_indicator = p%v_pf(tr%ma) - p%v_pf(tr%mb)
      end if
   end function load_indicator

   !> Trace the branch at (alpha, exp(t)), follow the load path (control: map_control_*),
   !> keep the mechanisms and the competing loads; under gap control classify the
   !> gap-controlled cycle (wa_gapmech).
   subroutine probe(model, alpha, t, p, control)
      integer, intent(in) :: model, control
      real(wp), intent(in) :: alpha, t
      type(probe_type), intent(out) :: p
      type(params_type) :: params
      type(branch_type) :: br
      type(path_type) :: path
      type(trace_options) :: opts
      real(wp) :: nan
      integer :: i, n, zc
      character(len=256) :: msg

      msg = ""
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      p%v_fc = nan
      p%v_pf = nan
      p%f_start = nan
      p%ln_a_pf = nan
      p%ln_a_out = nan
      p%g_in = nan
      p%g_half = nan
      call new_params(alpha, exp(t), params, p%status, msg)
      if (p%status /= wa_ok) return
      opts%mean_gap = iand(control, map_control_gap) /= 0    ! load control needs P* only
      call trace_branch(model, params, br, p%status, msg, opts)
      if (p%status /= wa_ok) return
      ! a case-1 root born at the branch's first point changes the mechanisms of both
      ! controls (MD 302 and 402 at alpha ~0.03-0.2 under gap control)
      p%f_start = curve_residual(model, params, opts%a_start, curve_y_max)
      if (iand(control, map_control_gap) /= 0) then
         call gap_mechanisms_from_branch(model, params, br, p%mech(3), p%mech(4), p%status, &
            msg, ln_a_out=p%ln_a_out, g_in=p%g_in, g_half=p%g_half)
         if (p%status /= wa_ok) then
            p%mech = -1
            return
         end if
      end if
      if (iand(control, map_control_load) == 0) return
      call path_from_branch(model, params, br, path, p%status, msg, mechanisms_only=.true.)
      if (p%status /= wa_ok) then
         p%mech = -1
         return
      end if
      p%mech(1:2) = [path%fc_mechanism, path%pf_mechanism]
      do i = path%n, 1, -1
         if (path%event(i) /= event_pull_off) cycle
         if (path%a_star(i) >= opts%a_start) p%ln_a_pf = log(path%a_star(i)/a_point_pull_off)
         exit
      end do
      n = br%n
      p%v_fc(0) = br%p_star(n)
      p%v_fc(3) = 0.0_wp
      do i = 1, n                         ! the contact curve's a* -> 0 end (MD: after
         if (br%a_star(i) > 0.0_wp) then  ! the pieces without contact)
            p%v_pf(0) = br%p_star(i)
            exit
         end if
      end do
      do i = 2, n - 1
         zc = merge(1, 2, br%zone_case(i) == zone_inside)
         if (br%extremum(i) == 1) then
            if (.not. (p%v_fc(zc) >= br%p_star(i))) p%v_fc(zc) = br%p_star(i)
         else if (br%extremum(i) == -1) then
            if (.not. (p%v_pf(zc) <= br%p_star(i))) p%v_pf(zc) = br%p_star(i)
         end if
      end do
      if (n >= 2) then                    ! the end itself is a minimum of case 2
         if (br%p_star(n - 1) > br%p_star(n) .and. .not. (p%v_pf(2) <= br%p_star(n))) &
            p%v_pf(2) = br%p_star(n)
      end if
   end subroutine probe

   !> Region grid at the alpha values not scanned: the mechanisms at the lowest mu (one
   !> load path) carried upward across the curves that pass this alpha.
   subroutine fill_regions(map)
      type(map_type), intent(inout) :: map
      type(probe_type) :: pr
      real(wp) :: mu_b(max_boundaries)
      integer :: to(max_boundaries), j, which, c, p, nb, i, m, k, order(max_boundaries)
      do j = 1, size(map%alpha)
         if (any(map%fc_region(:, j) /= -1) .or. any(map%ga_region(:, j) /= -1)) cycle
         call probe(map%model, map%alpha(j), log(map%mu(1)), pr, map%control)   ! not scanned
         map%n_paths = map%n_paths + 1
         if (pr%status /= wa_ok) cycle
         do which = 1, 4
            if (pr%mech(which) < 0) cycle
            nb = 0
            do c = 1, map%n_boundaries
               associate (b => map%boundary(c))
                  if (b%which /= which) cycle
                  do p = 1, b%n
                     if (b%alpha(p) == map%alpha(j) .and. nb < size(mu_b)) then
                        nb = nb + 1
                        mu_b(nb) = b%mu(p)
                        to(nb) = b%mech_above
                     end if
                  end do
               end associate
            end do
            order(1:nb) = sort_index(mu_b(1:nb))
            m = pr%mech(which)
            k = 1
            do i = 1, size(map%mu)
               do while (k <= nb)
                  if (mu_b(order(k)) > map%mu(i)) exit
                  m = to(order(k))
                  k = k + 1
               end do
               select case (which)
               case (1)
                  map%fc_region(i, j) = m
               case (2)
                  map%pf_region(i, j) = m
               case (3)
                  map%ga_region(i, j) = m
               case default
                  map%gr_region(i, j) = m
               end select
            end do
         end do
      end do
   end subroutine fill_regions

   pure function sort_index(v) result(idx)
      real(wp), intent(in) :: v(:)
      integer :: idx(size(v)), i, j, tmp
      idx = [(i, i = 1, size(v))]
      do i = 2, size(v)
         j = i
         do while (j > 1)
            if (v(idx(j - 1)) <= v(idx(j))) exit
            tmp = idx(j)
            idx(j) = idx(j - 1)
            idx(j - 1) = tmp
            j = j - 1
         end do
      end do
   end function sort_index

end module wa_map
