!> display: none
!>
!> Numbers as text for the library's messages (the library never prints: these build the
!> message strings that every routine returns with its status).
module wa_text
   use wa_kinds, only: wp
   implicit none
   private

   public :: real_text, int_text

contains

   !> A real in ES format with a 3-digit exponent, e.g. 7.9369860901363931E-001.
   pure function real_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(es24.16e3)') x
      text = trim(adjustl(buf))
   end function real_text

   !> An integer with no padding, e.g. 42.
   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=12) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function int_text

end module wa_text
