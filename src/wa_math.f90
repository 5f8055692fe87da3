!> display: none
!>
!> Elementary functions Fortran lacks, written to keep full relative accuracy, and the
!> small array helpers (an index sort) the library shares.
module wa_math
   use wa_kinds, only: wp, pi
   implicit none
   private

   public :: log1p, sincos_pi, sin_pi_sum, sqrt_sin_pi, sqrt_sin_pi_sum, edge_asinh, sort_index

   !> Below this x, sin(pi x) = pi x to rounding ((pi x)^2/6 < 1e-299)
   real(wp), parameter :: small_angle = 1.0e-150_wp
   real(wp), parameter :: sqrt_pi = 1.7724538509055160272981674833411452_wp

contains

   !> ln(1 + x), accurate for small |x| (Goldberg's correction of the rounded 1 + x).
   elemental function log1p(x) result(y)
      real(wp), intent(in) :: x
      real(wp) :: y
      real(wp) :: u
      u = 1.0_wp + x
      if (u == 1.0_wp) then
         y = x
      else
         y = log(u)*(x/(u - 1.0_wp))
      end if
   end function log1p

   !> sin(pi x) and cos(pi x) for x in [0, 1/2], both to full relative accuracy, from one
   !> sin/cos pair of the smaller angle (one sincos call): cos(pi x) = sin(pi (1/2 - x)),
   !> with 1/2 - x exact for x >= 1/4.
   elemental subroutine sincos_pi(x, s, c)
      real(wp), intent(in) :: x
      real(wp), intent(out) :: s, c
      real(wp) :: angle
      if (x <= 0.25_wp) then
         angle = pi*x
         s = sin(angle)
         c = cos(angle)
      else
         angle = pi*(0.5_wp - x)
         s = cos(angle)
         c = sin(angle)
      end if
   end subroutine sincos_pi

   !> sin(pi (u + v)) for u, v in [0, 1/2], from 1 - u - v = (1/2 - u) + (1/2 - v) past 1/2.
   elemental function sin_pi_sum(u, v) result(y)
      real(wp), intent(in) :: u, v
      real(wp) :: y
      if (u + v <= 0.5_wp) then
         y = sin(pi*(u + v))
      else
         y = sin(pi*((0.5_wp - u) + (0.5_wp - v)))
      end if
   end function sin_pi_sum

   !> sqrt(sin(pi x)) for x in [0, 1/2], to full relative accuracy down to the smallest
   !> subnormal x: below small_angle as sqrt(pi) sqrt(x) (pi x itself would be rounded to
   !> the subnormal grid, a 30 % step at x = 5e-324).
   elemental function sqrt_sin_pi(x) result(y)
      real(wp), intent(in) :: x
      real(wp) :: y
      if (x < small_angle) then
         y = sqrt_pi*sqrt(x)
      else
         y = sqrt(sin(pi*x))
      end if
   end function sqrt_sin_pi

   !> sqrt(sin(pi (u + v))) for u, v in [0, 1/2] (sqrt_sin_pi where u + v is small).
   elemental function sqrt_sin_pi_sum(u, v) result(y)
      real(wp), intent(in) :: u, v
      real(wp) :: y
      if (u + v < small_angle) then
         y = sqrt_sin_pi(u + v)
      else
         y = sqrt(sin_pi_sum(u, v))
      end if
   end function sqrt_sin_pi_sum

   !> asinh(r/A), r/A = sqrt(S^2 - A^2)/A, outside a contact of half-width a*
   !> (0 < a* < x <= 1/2; A = sin(pi a*), S = sin(pi x), S^2 - A^2 = sin(pi (x - a*))
   !> sin(pi (x + a*))). r/A = t1 t2, t1, t2 the root ratios (< 3e161 each), and where
   !> their product could overflow asinh = ln 2 + ln t1 + ln t2 (1/(4 t^2) < 1e-200 then):
   !> neither A nor A^2 is formed (a* down to 5e-324).
   elemental function edge_asinh(a_star, x) result(y)
      real(wp), intent(in) :: a_star, x
      real(wp) :: y, root_a, t1, t2
      root_a = sqrt_sin_pi(a_star)
      t1 = sqrt_sin_pi(x - a_star)/root_a
      t2 = sqrt_sin_pi_sum(x, a_star)/root_a
      if (t1 < 1.0e100_wp .and. t2 < 1.0e100_wp) then
         y = asinh(t1*t2)
      else
         y = log(2.0_wp) + log(t1) + log(t2)
      end if
   end function edge_asinh

   !> The permutation that sorts v into increasing order (insertion sort: stable, for the
   !> short arrays it is used on).
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

end module wa_math
