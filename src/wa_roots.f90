!> display: none
!>
!> Bracketed scalar root finding by Brent's method in reverse communication: the
!> caller evaluates the function, so no callbacks, closures or module state are
!> needed and everything stays pure. Usage:
!>   call brent_init(solver, x1, f1, x2, f2, xtol)   ! f1*f2 <= 0 (a bracket)
!>   do iter = 1, max_iter
!>      call brent_propose(solver, x, done); if (done) exit
!>      call brent_accept(solver, f(x))
!>   end do
!>   root = solver%b
!> Likewise the two one-dimensional minimisers: Brent's (golden sections and parabolic
!> steps; minimum_*) and the plain golden section (golden_*):
!>   call minimum_init(mn, a, b, xtol)
!>   do iter = 1, max_iter
!>      call minimum_propose(mn, x, done); if (done) exit
!>      call minimum_accept(mn, f(x))     ! mn%improved: x is the best point so far
!>   end do
!>   x_min = mn%x
!>   call golden_init(gs, lo, hi, atol, rtol)
!>   do iter = 1, max_iter
!>      call golden_propose(gs, x, done, slot, moved); if (done) exit
!>      call golden_accept(gs, f(x))      ! the point in slot (1: left, 2: right)
!>   end do
module wa_roots
   use wa_kinds, only: wp
   implicit none
   private

   public :: brent_type, brent_init, brent_propose, brent_accept
   public :: minimum_type, minimum_init, minimum_propose, minimum_accept
   public :: golden_type, golden_init, golden_propose, golden_accept

   !> The golden-section fraction (3 - sqrt(5))/2
   real(wp), parameter :: golden = 0.3819660112501051518_wp

   !> Brent's state: b is the best estimate, [b, c] brackets the root.
   type :: brent_type
      real(wp) :: a = 0.0_wp, b = 0.0_wp, c = 0.0_wp
      real(wp) :: fa = 0.0_wp, fb = 0.0_wp, fc = 0.0_wp
      real(wp) :: d = 0.0_wp, e = 0.0_wp
      !> Absolute tolerance added to the relative 2 eps |b|.
      real(wp) :: xtol = 0.0_wp
   end type brent_type

   !> Brent's minimiser (Brent 1973, localmin): [a, b] brackets the minimum, x is the
   !> best point so far, w the second best, v the previous w; u the point proposed last.
   type :: minimum_type
      real(wp) :: a = 0.0_wp, b = 0.0_wp, x = 0.0_wp, w = 0.0_wp, v = 0.0_wp, u = 0.0_wp
      real(wp) :: fx = 0.0_wp, fw = 0.0_wp, fv = 0.0_wp, d = 0.0_wp, e = 0.0_wp
      !> Absolute tolerance in x
      real(wp) :: tol = 0.0_wp
      !> f at x is known (after the first minimum_accept)
      logical :: started = .false.
      !> The last minimum_accept made its point the best so far (x)
      logical :: improved = .false.
   end type minimum_type

   !> Golden section: [lo, hi] brackets the minimum, x1 < x2 the interior points (slots
   !> 1 and 2) with their values f1, f2.
   type :: golden_type
      real(wp) :: lo = 0.0_wp, hi = 0.0_wp, x1 = 0.0_wp, x2 = 0.0_wp
      real(wp) :: f1 = 0.0_wp, f2 = 0.0_wp
      !> converged when hi - lo <= atol + rtol |hi|
      real(wp) :: atol = 0.0_wp, rtol = 0.0_wp
      !> equal values keep the left part of the bracket (else the right)
      logical :: ties_left = .true.
      !> values known: 0, 1 (f1) or 2 (both); the slot of the pending point
      integer :: n_known = 0, slot = 0
   end type golden_type

contains

   !> Start from a bracket: f1 and f2 must not have the same strict sign.
   pure subroutine brent_init(solver, x1, f1, x2, f2, xtol)
      type(brent_type), intent(out) :: solver
      real(wp), intent(in) :: x1, f1, x2, f2, xtol
      solver%a = x1
      solver%fa = f1
      solver%b = x2
      solver%fb = f2
      solver%c = x2
      solver%fc = f2
      solver%xtol = xtol
   end subroutine brent_init

   !> Next abscissa to evaluate, or done = .true. when b is converged. settle (default
   !> .false.): b is also converged when the interpolation puts the root within the
   !> tolerance of b (Brent would then spend evaluations closing the far end of the
   !> bracket, one tolerance step at a time, against the rounding noise of f).
   pure subroutine brent_propose(solver, x, done, settle)
      type(brent_type), intent(inout) :: solver
      real(wp), intent(out) :: x
      logical, intent(out) :: done
      logical, intent(in), optional :: settle
      real(wp) :: tol1, xm, p, q, r, s

      associate (a => solver%a, b => solver%b, c => solver%c, fa => solver%fa, &
            fb => solver%fb, fc => solver%fc, d => solver%d, e => solver%e)
         if ((fb > 0.0_wp .and. fc > 0.0_wp) .or. (fb < 0.0_wp .and. fc < 0.0_wp)) then
            c = a; fc = fa; d = b - a; e = d
         end if
         if (abs(fc) < abs(fb)) then
            a = b; b = c; c = a
            fa = fb; fb = fc; fc = fa
         end if
         tol1 = 2.0_wp*epsilon(1.0_wp)*abs(b) + 0.5_wp*solver%xtol
         xm = 0.5_wp*(c - b)
         done = abs(xm) <= tol1 .or. fb == 0.0_wp
         x = b
         if (done) return
         if (abs(e) >= tol1 .and. abs(fa) > abs(fb)) then
            s = fb/fa
            if (a == c) then          ! secant
               p = 2.0_wp*xm*s
               q = 1.0_wp - s
            else                      ! inverse quadratic interpolation
               q = fa/fc
               r = fb/fc
               p = s*(2.0_wp*xm*q*(q - r) - (b - a)*(r - 1.0_wp))
               q = (q - 1.0_wp)*(r - 1.0_wp)*(s - 1.0_wp)
            end if
            if (p > 0.0_wp) q = -q
            p = abs(p)
            if (2.0_wp*p < min(3.0_wp*xm*q - abs(tol1*q), abs(e*q))) then
               e = d; d = p/q
            else
               d = xm; e = d
            end if
         else
            d = xm; e = d
         end if
         if (abs(d) <= tol1 .and. present(settle)) then
            if (settle) then       ! an interpolation step (a bisection step is > tol1)
               done = .true.
               return
            end if
         end if
         a = b; fa = fb
         if (abs(d) > tol1) then
            b = b + d
         else
            b = b + sign(tol1, xm)
         end if
         x = b
      end associate
   end subroutine brent_propose

   !> Hand back f at the abscissa returned by the last brent_propose.
   pure subroutine brent_accept(solver, fx)
      type(brent_type), intent(inout) :: solver
      real(wp), intent(in) :: fx
      solver%fb = fx
   end subroutine brent_accept

   !> Start Brent's minimiser on the bracket [a, b] (a < b).
   pure subroutine minimum_init(mn, a, b, xtol)
      !> the minimiser's state
      type(minimum_type), intent(out) :: mn
      !> the bracket, a < b
      real(wp), intent(in) :: a, b
      !> absolute tolerance in x (> 0)
      real(wp), intent(in) :: xtol
      mn%a = a; mn%b = b
      mn%x = a + golden*(b - a); mn%v = mn%x; mn%w = mn%x; mn%u = mn%x
      mn%tol = xtol
   end subroutine minimum_init

   !> The next abscissa to evaluate (first the golden point of the bracket), or done when
   !> x is converged: within 2 tol of the bracket's midpoint, tol away from its ends.
   pure subroutine minimum_propose(mn, x, done)
      type(minimum_type), intent(inout) :: mn
      real(wp), intent(out) :: x
      logical, intent(out) :: done
      real(wp) :: m, t2, pp, q, rr
      done = .false.
      x = mn%x
      if (.not. mn%started) return
      associate (a => mn%a, b => mn%b, xb => mn%x, w => mn%w, v => mn%v, fx => mn%fx, &
            fw => mn%fw, fv => mn%fv, d => mn%d, e => mn%e, tol => mn%tol)
         m = 0.5_wp*(a + b)
         t2 = 2.0_wp*tol
         if (abs(xb - m) <= t2 - 0.5_wp*(b - a)) then
            done = .true.
            return
         end if
         pp = 0.0_wp; q = 0.0_wp; rr = 0.0_wp
         if (abs(e) > tol) then                   ! a parabola through x, w, v
            rr = (xb - w)*(fx - fv)
            q = (xb - v)*(fx - fw)
            pp = (xb - v)*q - (xb - w)*rr
            q = 2.0_wp*(q - rr)
            if (q > 0.0_wp) then
               pp = -pp
            else
               q = -q
            end if
            rr = e
            e = d
         end if
         if (abs(pp) < abs(0.5_wp*q*rr) .and. pp > q*(a - xb) .and. pp < q*(b - xb)) then
            d = pp/q
            mn%u = xb + d
            if (mn%u - a < t2 .or. b - mn%u < t2) d = sign(tol, m - xb)
         else                                     ! a golden section
            e = merge(b - xb, a - xb, xb < m)
            d = golden*e
         end if
         mn%u = xb + merge(d, sign(tol, d), abs(d) >= tol)
         x = mn%u
      end associate
   end subroutine minimum_propose

   !> Hand back f at the abscissa of the last minimum_propose.
   pure subroutine minimum_accept(mn, fu)
      type(minimum_type), intent(inout) :: mn
      real(wp), intent(in) :: fu
      if (.not. mn%started) then
         mn%fx = fu; mn%fv = fu; mn%fw = fu
         mn%started = .true.
         mn%improved = .true.
         return
      end if
      associate (a => mn%a, b => mn%b, x => mn%x, w => mn%w, v => mn%v, u => mn%u, &
            fx => mn%fx, fw => mn%fw, fv => mn%fv)
         mn%improved = fu <= fx
         if (mn%improved) then
            if (u < x) then
               b = x
            else
               a = x
            end if
            v = w; fv = fw; w = x; fw = fx; x = u; fx = fu
         else
            if (u < x) then
               a = u
            else
               b = u
            end if
            if (fu <= fw .or. w == x) then
               v = w; fv = fw; w = u; fw = fu
            else if (fu <= fv .or. v == x .or. v == w) then
               v = u; fv = fu
            end if
         end if
      end associate
   end subroutine minimum_accept

   !> Start a golden section on the bracket [lo, hi] (lo < hi).
   pure subroutine golden_init(gs, lo, hi, atol, rtol, ties_left)
      !> the section's state
      type(golden_type), intent(out) :: gs
      !> the bracket, lo < hi
      real(wp), intent(in) :: lo, hi
      !> converged when hi - lo <= atol + rtol |hi|
      real(wp), intent(in) :: atol, rtol
      !> equal values keep the left part of the bracket (default .true.)
      logical, intent(in), optional :: ties_left
      gs%lo = lo; gs%hi = hi
      gs%x1 = lo + golden*(hi - lo); gs%x2 = hi - golden*(hi - lo)
      gs%atol = atol; gs%rtol = rtol
      if (present(ties_left)) gs%ties_left = ties_left
   end subroutine golden_init

   !> The next abscissa to evaluate, the slot it takes (1: the left interior point, 2: the
   !> right) and whether the point held in that slot moved to the other one (the caller's
   !> data for the points move alike); or done when the bracket is converged.
   pure subroutine golden_propose(gs, x, done, slot, moved)
      type(golden_type), intent(inout) :: gs
      real(wp), intent(out) :: x
      logical, intent(out) :: done, moved
      integer, intent(out) :: slot
      logical :: left
      done = .false.
      moved = .false.
      if (gs%n_known < 2) then                ! the first two points
         slot = gs%n_known + 1
         x = merge(gs%x1, gs%x2, slot == 1)
         gs%slot = slot
         return
      end if
      if (gs%hi - gs%lo <= gs%atol + gs%rtol*abs(gs%hi)) then
         done = .true.
         x = merge(gs%x1, gs%x2, gs%f1 <= gs%f2)
         slot = 0
         return
      end if
      if (gs%ties_left) then
         left = gs%f1 <= gs%f2
      else
         left = gs%f1 < gs%f2
      end if
      moved = .true.
      if (left) then                          ! the minimum is in [lo, x2]
         gs%hi = gs%x2; gs%x2 = gs%x1; gs%f2 = gs%f1
         gs%x1 = gs%lo + golden*(gs%hi - gs%lo)
         slot = 1
      else                                    ! in [x1, hi]
         gs%lo = gs%x1; gs%x1 = gs%x2; gs%f1 = gs%f2
         gs%x2 = gs%hi - golden*(gs%hi - gs%lo)
         slot = 2
      end if
      x = merge(gs%x1, gs%x2, slot == 1)
      gs%slot = slot
   end subroutine golden_propose

   !> Hand back f at the abscissa of the last golden_propose.
   pure subroutine golden_accept(gs, fx)
      type(golden_type), intent(inout) :: gs
      real(wp), intent(in) :: fx
      if (gs%slot == 1) then
         gs%f1 = fx
      else
         gs%f2 = fx
      end if
      gs%n_known = min(gs%n_known + 1, 2)
   end subroutine golden_accept

end module wa_roots
