!> display: none
!>
!> Following one boundary curve of the adhesion map over the alpha grid: each next point
!> predicted by extrapolating the last three or four in (ln alpha, ln mu), bracketed by two
!> probes and refined by a safeguarded secant on the indicator of the pair of mechanisms
!> (bisection whenever the secant does not halve the bracket); every trial mu is classified
!> by its own probe, so each point is a bracket of the change to tol_t in ln mu. A curve
!> that cannot be continued ends where it is located by halving the step in ln alpha.
module wa_map_curve
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_not_converged
   use wa_validate, only: optval
   use wa_map_types, only: map_boundary, map_control_load, map_end_grid, map_end_inside, &
      map_end_mu_range, map_end_failed
   use wa_map_probe, only: probe_type, probe, probe_indicator, first_indicator, ind_none, &
      ind_loads
   implicit none
   private

   public :: tracker_type, continue_curve, refine

   !> Relative width in mu of the final bracket of every boundary point
   real(wp), parameter :: tol_t = 2.0e-9_wp
   !> Relative accuracy in alpha of a located start or end of a curve
   real(wp), parameter :: tol_alpha = 1.0e-6_wp

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
      if (tr%slope /= 0.0_wp .and. .not. optval(bracket_only, .false.)) then
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
      ! enough to know the curve is there (and not another change of the same pair, farther off)
      if (optval(bracket_only, .false.)) then
         t = 0.5_wp*(t0 + t1)
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

      tol = optval(tol_in, tol_t)
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
      tr%ind = first_indicator(p_lo, p_hi, tr%which, tr%ma, tr%mb)
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
   !> The indicator of the tracker's kind tr%ind at p (NaN where missing).
   pure real(wp) function indicator(tr, p)
      type(tracker_type), intent(in) :: tr
      type(probe_type), intent(in) :: p
      indicator = probe_indicator(p, tr%ind, tr%which, tr%ma, tr%mb)
   end function indicator


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
      tr%ind = first_indicator(ps(i_lo), ps(i_hi), tr%which, tr%ma, tr%mb)
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


end module wa_map_curve
