!> Working precision and the few named constants every module shares.
module wa_kinds
   use, intrinsic :: iso_c_binding, only: c_double, c_int
   implicit none
   private

   !> Working precision: C double, so the C and Python layers pass reals unchanged.
   integer, parameter, public :: wp = c_double
   !> Integer kind of everything that crosses the C boundary.
   integer, parameter, public :: ip = c_int

   real(wp), parameter, public :: pi = 3.141592653589793238462643383279502884_wp
   real(wp), parameter, public :: half_pi = 0.5_wp*pi

end module wa_kinds
