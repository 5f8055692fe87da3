!> Closed forms that need no solve: Westergaard and JKR loads, and the Westergaard
!> pressure, surface displacement and gap over a period. Everything is dimensionless
!> (MODEL-NOTES.md): x* = x/L, pressures by p* = pi E* Delta / L, lengths by Delta.
!> Outside the domain 0 <= a* <= 1/2 (or NaN input) these elemental functions return NaN:
!> they have no status argument; the equilibrium solvers validate and report instead.
module wa_kernels
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_negative_inf
   use wa_kinds, only: wp, pi
   implicit none
   private

   public :: westergaard_load, jkr_load
   public :: westergaard_pressure, westergaard_displacement, westergaard_gap
   public :: wavy_gap_shape

contains

   !> Westergaard load P* = sin^2(pi a*)   (2.4), (3.1)
   elemental function westergaard_load(a_star) result(p)
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
      real(wp), intent(in) :: alpha, a_star
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
      ! tan(pi a*) = sin/cos with cos(pi a*) = sin(pi (1/2 - a*)) accurate near a* = 1/2
      p = sin(pi*a_star)**2 - alpha*sqrt(sin(pi*a_star)/sin(pi*(0.5_wp - a_star)))
   end function jkr_load

   !> Westergaard contact pressure p/p* = 2 cos(pi x*) sqrt(A^2 - sin^2(pi x*)) for
   !> |x*| <= a* (periodic in x* with period 1), zero elsewhere   (2.3a)
   elemental function westergaard_pressure(a_star, x_star) result(p)
      real(wp), intent(in) :: a_star, x_star
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
      if (xr < a_star) p = 2.0_wp*cos(pi*xr)*sqrt(max(0.0_wp, (a - s)*(a + s)))
   end function westergaard_pressure

   !> Surface normal displacement relative to the contact centre, u_z/Delta   (2.6)
   !>   cos(2 pi x*) - 1                                        for |x*| <= a*
   !>   cos(2 pi x*) - 1 + 2 S sqrt(S^2-A^2) - 2 A^2 ln((S + sqrt(S^2-A^2))/A)  beyond
   elemental function westergaard_displacement(a_star, x_star) result(u)
      real(wp), intent(in) :: a_star, x_star
      real(wp) :: u
      real(wp) :: xr
      if (.not. in_half_period(a_star) .or. x_star /= x_star) then
         u = ieee_value(u, ieee_quiet_nan)
         return
      end if
      xr = reduced_x(x_star)
      u = -2.0_wp*sin(pi*xr)**2 + wavy_gap_shape(sin(pi*a_star), sin(pi*xr))
   end function westergaard_displacement

   !> Gap between the surfaces, h/Delta, zero in the contact   (2.15a) with (2.6)
   !>   h/Delta = 2 [S sqrt(S^2-A^2) - A^2 ln((S + sqrt(S^2-A^2))/A)],  S = sin(pi x*) >= A
   elemental function westergaard_gap(a_star, x_star) result(h)
      real(wp), intent(in) :: a_star, x_star
      real(wp) :: h
      if (.not. in_half_period(a_star) .or. x_star /= x_star) then
         h = ieee_value(h, ieee_quiet_nan)
         return
      end if
      h = wavy_gap_shape(sin(pi*a_star), sin(pi*reduced_x(x_star)))
   end function westergaard_gap

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
