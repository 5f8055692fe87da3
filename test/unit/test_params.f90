!> Parameters: validation, derived quantities, SI conversion.
module test_params
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
   use wavyadhesion
   use wa_kinds, only: wp, pi
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_params

contains

   subroutine collect_params(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("derived_quantities", test_derived), &
         new_unittest("invalid_alpha_mu", test_invalid), &
         new_unittest("dimensional_round_trip", test_dimensional), &
         new_unittest("invalid_dimensional", test_invalid_dimensional)]
   end subroutine collect_params

   subroutine test_derived(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      integer :: status
      call new_params(0.3_wp, 1.0_wp, p, status)
      call check(error, status == wa_ok, "status")
      call check_close(error, p%sigma0, pi*(0.09_wp/32.0_wp)**(1.0_wp/3.0_wp), 1.0e-15_wp, what="Sigma0")
      call check_close(error, p%dcod, (0.3_wp**4/2.0_wp)**(1.0_wp/3.0_wp), 1.0e-15_wp, what="Dcod")
      call new_params(0.3_wp, 0.0_wp, p, status)
      call check(error, status == wa_ok .and. p%sigma0 == 0.0_wp .and. p%dcod > huge(1.0_wp), &
         "mu = 0: Sigma0 = 0, Dcod = +Infinity")
   end subroutine test_derived

   subroutine test_invalid(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      character(len=256) :: msg
      real(wp) :: nan, inf
      integer :: status
      nan = ieee_value(nan, ieee_quiet_nan)
      inf = ieee_value(inf, ieee_positive_inf)
      msg = ""
      call new_params(0.0_wp, 1.0_wp, p, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "alpha") > 0 &
         .and. index(msg, "[1e-12, 1e12]") > 0, "alpha = 0: "//trim(msg))
      msg = ""
      call new_params(nan, 1.0_wp, p, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "alpha") > 0, "alpha NaN")
      msg = ""
      call new_params(0.3_wp, -1.0_wp, p, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "mu") > 0, "mu < 0")
      call new_params(0.3_wp, inf, p, status)
      call check(error, status == wa_invalid_argument, "mu = inf")
      call new_params(inf, 1.0_wp, p, status)
      call check(error, status == wa_invalid_argument, "alpha = inf")
      ! the supported domain (doc/theory.md, "Supported range"): its ends are accepted,
      ! beyond them and 0 < mu < 1e-100 are refused with the range in the message
      call new_params(1.0e-12_wp, 1.0e-100_wp, p, status)
      call check(error, status == wa_ok, "alpha = 1e-12, mu = 1e-100 accepted")
      call new_params(1.0e12_wp, 1.0e100_wp, p, status)
      call check(error, status == wa_ok, "alpha = 1e12, mu = 1e100 accepted")
      call new_params(0.3_wp, 0.0_wp, p, status)
      call check(error, status == wa_ok, "mu = 0 accepted")
      msg = ""
      call new_params(0.3_wp, 1.0e-310_wp, p, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "0 or [1e-100, 1e100]") &
         > 0 .and. index(msg, "E-310") > 0, "denormal mu: "//trim(msg))
      msg = ""
      call new_params(huge(1.0_wp), 1.0_wp, p, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "E+308") > 0, &
         "alpha = DBL_MAX: "//trim(msg))
      call new_params(0.3_wp, 1.0e101_wp, p, status)
      call check(error, status == wa_invalid_argument, "mu = 1e101")
   end subroutine test_invalid

   !> SI in, dimensionless out, and mu equals its dimensional form
   !> 4 sigma0 (R/(pi^2 E*^2 dgamma))^(1/3) (corrected (2.19), doc/theory.md "Parameters").
   subroutine test_dimensional(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      type(scales_type) :: sc
      real(wp) :: estar, period, delta, dgamma, sigma0, radius
      integer :: status
      call reduced_modulus(1.0e9_wp, 0.3_wp, 2.0e11_wp, 0.25_wp, estar, status)
      call check_close(error, estar, 1.0_wp/(0.91_wp/1.0e9_wp + 0.9375_wp/2.0e11_wp), &
         1.0e-15_wp, what="E*")
      period = 1.0e-5_wp; delta = 1.0e-7_wp; dgamma = 0.05_wp; sigma0 = 1.0e7_wp
      call dimensional_params(estar, period, delta, dgamma, sigma0, p, sc, status)
      call check(error, status == wa_ok, "status")
      radius = period**2/(4.0_wp*pi**2*delta)
      call check_close(error, p%alpha, 4.0_wp*pi*radius*sqrt(2.0_wp*dgamma/(estar*period**3)), &
         1.0e-14_wp, what="alpha (2.21)")
      call check_close(error, p%mu, 4.0_wp*sigma0*(radius/(pi**2*estar**2*dgamma))**(1.0_wp/3.0_wp), &
         1.0e-14_wp, what="mu (2.19)")
      call check_close(error, p%sigma0*sc%pressure, sigma0, 1.0e-14_wp, what="Sigma0 p* = sigma0")
      call check_close(error, sc%force, pi*estar*delta, 1.0e-15_wp, what="p* L")
      call check_close(error, p%dcod, 2.0_wp*pi**2*radius*dgamma/(period**2*sigma0), &
         1.0e-14_wp, what="Dcod (A4)")
   end subroutine test_dimensional

   subroutine test_invalid_dimensional(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      type(scales_type) :: sc
      character(len=256) :: msg
      real(wp) :: estar
      integer :: status
      msg = ""
      call dimensional_params(1.0e9_wp, -1.0_wp, 1.0e-7_wp, 0.05_wp, 1.0e7_wp, p, sc, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "period") > 0, trim(msg))
      msg = ""
      call reduced_modulus(1.0e9_wp, 0.7_wp, 1.0e9_wp, 0.3_wp, estar, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "nu1") > 0, trim(msg))
   end subroutine test_invalid_dimensional

end module test_params
