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
module wa_roots
   use wa_kinds, only: wp
   implicit none
   private

   public :: brent_type, brent_init, brent_propose, brent_accept

   !> Brent's state: b is the best estimate, [b, c] brackets the root.
   type :: brent_type
      real(wp) :: a = 0.0_wp, b = 0.0_wp, c = 0.0_wp
      real(wp) :: fa = 0.0_wp, fb = 0.0_wp, fc = 0.0_wp
      real(wp) :: d = 0.0_wp, e = 0.0_wp
      !> Absolute tolerance added to the relative 2 eps |b|.
      real(wp) :: xtol = 0.0_wp
   end type brent_type

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

end module wa_roots
