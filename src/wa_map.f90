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
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   use wa_validate, only: optval
   use wa_math, only: sort_index
   use wa_params, only: alpha_min, alpha_max, mu_min, mu_max
   use wa_state, only: model_dw, model_md
   use wa_map_types, only: map_type, map_boundary, map_point, boundary_code, &
      map_control_load, map_control_gap, map_control_both, map_end_inside, map_end_failed, &
      map_point_meet, map_point_turn, map_point_end, map_point_fail
   use wa_map_probe, only: probe_type, probe
   use wa_map_curve, only: tracker_type, continue_curve, refine
   implicit none
   private

   public :: adhesion_map
   !> adhesion_map's argument types and codes, for its callers
   public :: map_type, map_control_load, map_control_gap, map_control_both
   !> Bounds on adhesion_map's grid, for its callers (the Python and C layers check them first)
   public :: map_n_mu_max, map_n_alpha_max, map_cells_max

   !> Bound on the curves of one map, and on those of load control (which 1, 2) and of gap
   !> control (3, 4) each: a tangle of one control does not crowd out the other
   integer, parameter :: max_boundaries = 128, max_per_control = 64
   !> Bounds on the grid (checked before anything is allocated): at most map_n_mu_max mu
   !> and map_n_alpha_max alpha values, at most map_cells_max cells n_mu*n_alpha (each
   !> cell holds four mechanism codes)
   integer, parameter :: map_n_mu_max = 100000, map_n_alpha_max = 100000, &
      map_cells_max = 10000000

contains

   !> Build the map of `model` (model_dw or model_md) over the increasing grid alpha(:)
   !> and n_mu log-spaced mu in [mu_lo, mu_hi]. scan_every (default 20): the coarse mu scan
   !> that discovers boundaries runs at every scan_every-th alpha (and the last).
   !> control (default map_control_load): map_control_gap for the gap-control boundaries
   !> (approach, retraction: codes 3xx, 4xx) only, map_control_both for all.
   !> status: wa_invalid_argument for bad input (errmsg names it), else wa_ok; boundaries
   !> that cannot be continued end with end_kind = map_end_failed, never with a wrong point.
   subroutine adhesion_map(model, alpha, mu_lo, mu_hi, n_mu, map, status, errmsg, scan_every, &
         control)
      !> The model: model_dw or model_md (the others have no mechanism changes to map)
      integer, intent(in) :: model
      !> Johnson's parameter alpha at every column of the map: 1 to map_n_alpha_max values,
      !> strictly increasing, each in [alpha_min, alpha_max]
      real(wp), intent(in) :: alpha(:)
      !> Smallest mu of the map, in [mu_min, mu_max], below mu_hi
      real(wp), intent(in) :: mu_lo
      !> Largest mu of the map, in [mu_min, mu_max]
      real(wp), intent(in) :: mu_hi
      !> Number of log-spaced mu rows of the region grid, in [2, map_n_mu_max]; n_mu times
      !> size(alpha) at most map_cells_max
      integer, intent(in) :: n_mu
      !> The map: grids, region mechanisms, boundary curves and special points
      type(map_type), intent(out) :: map
      !> wa_ok, or wa_invalid_argument for bad input (curves that cannot be continued end
      !> with end_kind = map_end_failed instead)
      integer, intent(out) :: status
      !> Receives the reason on failure: the argument and its valid range
      character(len=*), intent(inout), optional :: errmsg
      !> The coarse mu scan runs at every scan_every-th alpha (and the last); >= 1, default 20
      integer, intent(in), optional :: scan_every
      !> Which boundaries: map_control_load (default), map_control_gap or map_control_both
      integer, intent(in), optional :: control
      integer :: every, j, na

      call check_input(model, alpha, mu_lo, mu_hi, n_mu, status, errmsg)
      if (status /= wa_ok) return
      every = optval(scan_every, 20)
      if (every < 1) then
         call set_error(wa_invalid_argument, "adhesion_map: scan_every must be >= 1", &
            status, errmsg)
         return
      end if
      map%control = optval(control, map_control_load)
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

end module wa_map
