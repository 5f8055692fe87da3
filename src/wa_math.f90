!> Elementary functions Fortran lacks, written to keep full relative accuracy.
module wa_math
   use wa_kinds, only: wp
   implicit none
   private

   public :: log1p

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

end module wa_math
