!> Tests of wa_text, the numbers in the library's messages: the expected texts are
!> Python's '%.16E' of the same doubles with the exponent widened to 3 digits.
module test_text
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
      ieee_negative_inf
   use wa_kinds, only: wp
   use wa_text, only: real_text, int_text
   use harness, only: error_type, unittest_type, new_unittest, check
   implicit none
   private

   public :: collect_text

contains

   subroutine collect_text(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("real_text_format", test_real_format), &
         new_unittest("real_text_round_trip", test_real_round_trip), &
         new_unittest("real_text_not_finite", test_real_not_finite), &
         new_unittest("int_text", test_int)]
   end subroutine collect_text

   subroutine check_text(error, actual, expected)
      type(error_type), allocatable, intent(inout) :: error
      character(len=*), intent(in) :: actual, expected
      call check(error, actual == expected, "got '"//actual//"' expected '"//expected//"'")
   end subroutine check_text

   subroutine test_real_format(error)
      type(error_type), allocatable, intent(out) :: error
      call check_text(error, real_text(0.5_wp), "5.0000000000000000E-001")
      call check_text(error, real_text(0.0_wp), "0.0000000000000000E+000")
      call check_text(error, real_text(1.0_wp/3.0_wp), "3.3333333333333331E-001")
      call check_text(error, real_text(-1.0e300_wp), "-1.0000000000000001E+300")
      call check_text(error, real_text(huge(1.0_wp)), "1.7976931348623157E+308")
      call check_text(error, real_text(tiny(1.0_wp)), "2.2250738585072014E-308")
      call check_text(error, real_text(5.0e-324_wp), "4.9406564584124654E-324")
   end subroutine test_real_format

   !> 17 significant digits: reading the text back gives the same double.
   subroutine test_real_round_trip(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: xs(*) = [0.1_wp, 1.0_wp/3.0_wp, 0.79369860901363931_wp, &
         -2.0_wp**(-52), 1.0e-310_wp, 6.02214076e23_wp, nearest(1.0_wp, -1.0_wp)]
      character(len=:), allocatable :: text
      real(wp) :: y
      integer :: i
      do i = 1, size(xs)
         text = real_text(xs(i))
         read (text, *) y
         call check(error, y == xs(i), "round trip of "//real_text(xs(i)))
      end do
   end subroutine test_real_round_trip

   subroutine test_real_not_finite(error)
      type(error_type), allocatable, intent(out) :: error
      call check_text(error, real_text(ieee_value(1.0_wp, ieee_quiet_nan)), "NaN")
      call check_text(error, real_text(ieee_value(1.0_wp, ieee_positive_inf)), "Infinity")
      call check_text(error, real_text(ieee_value(1.0_wp, ieee_negative_inf)), "-Infinity")
   end subroutine test_real_not_finite

   subroutine test_int(error)
      type(error_type), allocatable, intent(out) :: error
      call check_text(error, int_text(0), "0")
      call check_text(error, int_text(42), "42")
      call check_text(error, int_text(-7), "-7")
      call check_text(error, int_text(huge(1)), "2147483647")
      call check_text(error, int_text(-huge(1) - 1), "-2147483648")
   end subroutine test_int

end module test_text
