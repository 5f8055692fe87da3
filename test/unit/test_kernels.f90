!> Closed-form kernels: Westergaard, JKR, Westergaard profiles.
module test_kernels
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use wavyadhesion
   use wa_kinds, only: wp, pi
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_kernels

contains

   subroutine collect_kernels(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("jkr_facts", test_jkr_facts), &
         new_unittest("pressure_mean_is_load", test_pressure_mean), &
         new_unittest("gap_and_displacement", test_gap), &
         new_unittest("outside_domain_is_nan", test_domain)]
   end subroutine collect_kernels

   !> JKR: the local maximum touches P* = 0 at pi a* = pi/3 for alpha = (3/4)^(3/4)/sqrt(2).
   subroutine test_jkr_facts(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: alpha, h
      alpha = (0.75_wp)**0.75_wp/sqrt(2.0_wp)
      h = 1.0e-6_wp
      call check_close(error, jkr_load(alpha, 1.0_wp/3.0_wp), 0.0_wp, 0.0_wp, 1.0e-15_wp, "P*(1/3)")
      call check_close(error, (jkr_load(alpha, 1.0_wp/3.0_wp + h) - jkr_load(alpha, 1.0_wp/3.0_wp - h)) &
         /(2*h), 0.0_wp, 0.0_wp, 1.0e-8_wp, "dP*/da* at 1/3")
      call check(error, jkr_load(alpha, 0.5_wp) < -huge(1.0_wp), "JKR at a* = 1/2 is -Infinity")
   end subroutine test_jkr_facts

   !> Mean Westergaard pressure over a period equals sin^2(pi a*)   (2.4)
   subroutine test_pressure_mean(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 100000
      real(wp) :: x(n)
      integer :: i
      x = [((real(i, wp) - 0.5_wp)/n - 0.5_wp, i=1, n)]
      call check_close(error, sum(westergaard_pressure(0.2_wp, x))/n, westergaard_load(0.2_wp), &
         0.0_wp, 1.0e-7_wp, "mean pressure")
   end subroutine test_pressure_mean

   !> h = f + u_z - delta: the gap is the displacement plus the profile 2 sin^2   (2.15a)
   subroutine test_gap(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: x
      x = 0.37_wp
      call check_close(error, westergaard_gap(0.2_wp, x), westergaard_displacement(0.2_wp, x) &
         + 2.0_wp*sin(pi*x)**2, 1.0e-14_wp, what="gap = u_z + f")
      call check(error, westergaard_gap(0.2_wp, 0.1_wp) == 0.0_wp, "no gap in contact")
      call check_close(error, westergaard_gap(0.0_wp, 0.5_wp), 2.0_wp, 1.0e-15_wp, &
         what="no contact: gap 2 Delta at x = L/2")
   end subroutine test_gap

   subroutine test_domain(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, ieee_is_nan(westergaard_load(0.6_wp)), "westergaard_load(0.6)")
      call check(error, ieee_is_nan(jkr_load(0.3_wp, -0.1_wp)), "jkr_load(a* < 0)")
      call check(error, ieee_is_nan(jkr_load(-1.0_wp, 0.1_wp)), "jkr_load(alpha < 0)")
      call check(error, ieee_is_finite(jkr_load(0.3_wp, 0.5_wp - 1.0e-12_wp)), "finite near 1/2")
   end subroutine test_domain

end module test_kernels
