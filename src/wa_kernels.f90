!> Closed forms that need no solve: Westergaard and JKR loads, and the Westergaard
!> pressure, surface displacement and gap over a period. Everything is dimensionless
!> (doc/theory.md, "Westergaard and JKR"): x* = x/L, pressures by p* = pi E* Delta / L, lengths by Delta.
!> Outside the domain 0 <= a* <= 1/2 (or NaN input) these elemental functions return NaN:
!> they have no status argument; the equilibrium solvers validate and report instead.
module wa_kernels
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_negative_inf
   use wa_kinds, only: wp, pi
   use wa_math, only: sqrt_sin_pi, sqrt_sin_pi_sum, edge_asinh, sin_pi_sum
   implicit none
   private

   public :: westergaard_load, jkr_load
   public :: westergaard_pressure, westergaard_displacement, westergaard_gap
   public :: wavy_gap_shape, small_contact_gap, shape

   !> Below this A = sin(pi a*) (a* < 4.7e-155), A^2 is subnormal or 0
   real(wp), parameter, public :: sqrt_tiny = 1.4916681462400413e-154_wp
   !> Below this a*, sin(pi a*) = pi a* to rounding
   real(wp), parameter :: small_angle = 1.0e-150_wp

contains

   !> Westergaard load P* = sin^2(pi a*)   (2.4), (3.1)
   elemental function westergaard_load(a_star) result(p)
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      real(wp) :: p
      if (.not. in_half_period(a_star)) then
         p = ieee_value(p, ieee_quiet_nan)
         return
      end if
      p = sin(pi*a_star)**2
   end function westergaard_load

   !> JKR load (Johnson 1995) P* = sin^2(pi a*) - alpha sqrt(tan(pi a*))   (2.26a), (3.4)
   !> At a* = 1/2 it is -Infinity (full contact never releases).
   elemental function jkr_load(alpha, a_star) result(p)
      !> Johnson's parameter alpha (dimensionless, (2.21)), >= 0
      real(wp), intent(in) :: alpha
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      real(wp) :: p
      if (.not. in_half_period(a_star) .or. .not. (alpha >= 0.0_wp) .or. alpha > huge(alpha)) then
         p = ieee_value(p, ieee_quiet_nan)
         return
      end if
      if (a_star == 0.5_wp) then
         p = ieee_value(p, ieee_negative_inf)
         if (alpha == 0.0_wp) p = 1.0_wp
         return
      end if
      if (a_star < small_angle) then
         ! tan = sin to rounding; sqrt(sin(pi a*)) without rounding pi a* to the subnormal grid
         p = sin(pi*a_star)**2 - alpha*sqrt_sin_pi(a_star)
         return
      end if
      ! tan(pi a*) = sin/cos with cos(pi a*) = sin(pi (1/2 - a*)) accurate near a* = 1/2
      p = sin(pi*a_star)**2 - alpha*sqrt(sin(pi*a_star)/sin(pi*(0.5_wp - a_star)))
   end function jkr_load

   !> Westergaard contact pressure p/p* = 2 cos(pi x*) sqrt(A^2 - sin^2(pi x*)) for
   !> |x*| <= a* (periodic in x* with period 1), zero elsewhere   (2.3a)
   elemental function westergaard_pressure(a_star, x_star) result(p)
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      !> Position over the period, x* = x/L (any real: period 1, crest at 0)
      real(wp), intent(in) :: x_star
      real(wp) :: p
      real(wp) :: xr, s, a
      if (.not. in_half_period(a_star) .or. x_star /= x_star) then
         p = ieee_value(p, ieee_quiet_nan)
         return
      end if
      xr = reduced_x(x_star)
      a = sin(pi*a_star)
      s = sin(pi*xr)
      p = 0.0_wp
      if (xr < a_star) then
         p = 2.0_wp*cos(pi*xr)*sqrt(max(0.0_wp, (a - s)*(a + s)))
         ! A^2 - S^2 = sin(pi (a* - x*)) sin(pi (a* + x*)) subnormal or 0 (a* < 1e-154):
         ! from the square roots of the two sines
         if ((a - s)*(a + s) < tiny(a)) p = 2.0_wp*cos(pi*xr)*sqrt_sin_pi(a_star - xr)* &
            sqrt_sin_pi_sum(a_star, xr)
      end if
   end function westergaard_pressure

   !> Surface normal displacement relative to the contact centre, u_z/Delta   (2.6)
   !>   cos(2 pi x*) - 1                                        for |x*| <= a*
   !>   cos(2 pi x*) - 1 + 2 S sqrt(S^2-A^2) - 2 A^2 ln((S + sqrt(S^2-A^2))/A)  beyond
   elemental function westergaard_displacement(a_star, x_star) result(u)
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      !> Position over the period, x* = x/L (any real: period 1, crest at 0)
      real(wp), intent(in) :: x_star
      real(wp) :: u
      real(wp) :: xr
      if (.not. in_half_period(a_star) .or. x_star /= x_star) then
         u = ieee_value(u, ieee_quiet_nan)
         return
      end if
      xr = reduced_x(x_star)
      u = -2.0_wp*sin(pi*xr)**2 + westergaard_gap(a_star, xr)
   end function westergaard_displacement

   !> Gap between the surfaces, h/Delta, zero in the contact   (2.15a) with (2.6)
   !>   h/Delta = 2 [S sqrt(S^2-A^2) - A^2 ln((S + sqrt(S^2-A^2))/A)],  S = sin(pi x*) >= A
   elemental function westergaard_gap(a_star, x_star) result(h)
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      !> Position over the period, x* = x/L (any real: period 1, crest at 0)
      real(wp), intent(in) :: x_star
      real(wp) :: h, t, xr
      if (.not. in_half_period(a_star) .or. x_star /= x_star) then
         h = ieee_value(h, ieee_quiet_nan)
         return
      end if
      xr = reduced_x(x_star)
      h = 0.0_wp
      if (xr <= a_star) return
      if (a_star > 0.0_wp .and. sin(pi*a_star) < sqrt_tiny) then
         call small_contact_gap(a_star, xr, h, t)
         return
      end if
      ! S^2 - A^2 = sin(pi (x* - a*)) sin(pi (x* + a*)): accurate also where A and S both
      ! round to 1 (a* -> 1/2)
      h = max(0.0_wp, shape(sin(pi*a_star), sin(pi*xr), &
         sqrt(sin(pi*(xr - a_star))*sin_pi_sum(xr, a_star))))
   end function westergaard_gap

   !> 2 [S r - A^2 asinh(r/A)]: the gap outside a Westergaard contact (A > 0), 2 S^2 at A = 0.
   !> With t = r/A it is 2 A^2 f(t), f = t sqrt(1+t^2) - asinh t = 2 sum_k c_k t^(2k+3)/(2k+3),
   !> c_k the coefficients of (1+u)^(-1/2): the series for t < 1/2 (DW multiplies the gap in
   !> the zone by 1 + lambda, up to 1e20, so it must keep its relative accuracy as t -> 0).
   elemental function shape(a, s, r) result(h)
      real(wp), intent(in) :: a, s, r
      real(wp) :: h
      real(wp) :: t, t2, term, ck, total
      integer :: k
      if (a <= 0.0_wp) then
         h = 2.0_wp*s*s
         return
      end if
      t = r/a
      if (t >= 0.5_wp) then
         h = 2.0_wp*(s*r - a*a*asinh(t))
         return
      end if
      t2 = t*t
      ck = 1.0_wp
      term = t*t2
      total = term/3.0_wp
      do k = 1, 40
         ck = -ck*real(2*k - 1, wp)/real(2*k, wp)
         term = term*t2
         total = total + ck*term/real(2*k + 3, wp)
         if (abs(term) < 1.0e-17_wp*total) exit
      end do
      h = 4.0_wp*a*a*total
   end function shape

   !> The Westergaard gap 2 [S r - A^2 asinh(r/A)] outside a contact with A = sin(pi a*)
   !> below sqrt_tiny (0 < a* < x* <= 1/2, subnormal a* included), and ash = asinh(r/A)
   !> (edge_asinh: r/A can overflow, A is rounded to the subnormal grid). A^2 asinh is below
   !> 1e-305: it matters only where S r is as small, so the absolute error stays below 1e-320.
   elemental subroutine small_contact_gap(a_star, x, h, ash)
      real(wp), intent(in) :: a_star, x
      real(wp), intent(out) :: h, ash
      real(wp) :: a
      a = sin(pi*a_star)
      ash = edge_asinh(a_star, x)
      h = 2.0_wp*(sin(pi*x)*sqrt_sin_pi(x - a_star)*sqrt_sin_pi_sum(x, a_star) - a*(a*ash))
      h = max(0.0_wp, h)
   end subroutine small_contact_gap

   !> 2 [S sqrt(S^2-A^2) - A^2 ln((S + sqrt(S^2-A^2))/A)] for S > A, else 0: the gap
   !> opened outside a Westergaard contact of half-width A (in units of Delta).
   !> The log is written as asinh(sqrt(S^2-A^2)/A) to stay accurate as S -> A.
   elemental function wavy_gap_shape(a, s) result(h)
      real(wp), intent(in) :: a, s
      real(wp) :: h
      real(wp) :: r
      h = 0.0_wp
      if (s <= a) return
      r = sqrt((s - a)*(s + a))
      if (a > 0.0_wp) then
         h = 2.0_wp*(s*r - a*a*asinh(r/a))
      else
         h = 2.0_wp*s*r
      end if
   end function wavy_gap_shape

   !> |x*| folded into the half period [0, 1/2].
   elemental function reduced_x(x_star) result(xr)
      real(wp), intent(in) :: x_star
      real(wp) :: xr
      xr = abs(x_star - anint(x_star))
   end function reduced_x

   elemental logical function in_half_period(a_star)
      real(wp), intent(in) :: a_star
      in_half_period = a_star >= 0.0_wp .and. a_star <= 0.5_wp
   end function in_half_period

end module wa_kernels
