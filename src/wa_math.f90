!> Elementary functions Fortran lacks, written to keep full relative accuracy, and the
!> small array helpers (an index sort) the library shares.
module wa_math
   use wa_kinds, only: wp, pi
   implicit none
   private

   public :: log1p, sincos_pi, sort_index

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
