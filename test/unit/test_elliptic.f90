!> Tests of wa_elliptic: the closed forms against mpmath references (study/verify/check_istar.py),
!> against tanh-sinh quadrature, the limits C = 1 and C -> A, and the extremes of the domain.
module test_elliptic
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan, ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument
   use wa_elliptic, only: istar_scaled, ia_star, istar_quadrature, istar_carlson
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_elliptic

   !> istar_scaled(a, c, d2, omc2) and W = I*/(C^2-A^2)^2 for exactly these doubles.
   type :: w_case
      real(wp) :: a, c, d2, omc2, w
   end type w_case

   !> ia_star(a, oma2) and I_A*.
   type :: ia_case
      real(wp) :: a, oma2, ia
   end type ia_case

   !> Tolerances: mpmath references (a few ulp), two of our own algorithms, quadrature.
   real(wp), parameter :: rtol_ref = 5.0e-15_wp, rtol_pair = 5.0e-15_wp, rtol_quad = 1.0e-13_wp

   !> Printed by `python3 study/verify/check_istar.py --fortran` (mp.dps = 40, tanh-sinh quadrature):
   !> interior, C -> A (relative gap 1e-16 ... 0.5), C -> 1 (1-C^2 down to 1e-40 and 0),
   !> A from 1e-12 to 1 - A^2 = 1e-17.
   type(w_case), parameter :: w_ref(*) = [ &
w_case(9.99999999999999980e-13_wp, 1.00000000000000018e-12_wp, 2.00000000000000027e-40_wp, &
             1.00000000000000000e+00_wp, 1.96349540849362061e+11_wp), &
      w_case(9.99999999999999980e-13_wp, 1.00000001000000007e-12_wp, 2.00000001000000013e-32_wp, &
             1.00000000000000000e+00_wp, 1.96349539867614380e+11_wp), &
      w_case(9.99999999999999980e-13_wp, 1.00100000000000008e-12_wp, 2.00099999999999996e-27_wp, &
             1.00000000000000000e+00_wp, 1.96251409015062531e+11_wp), &
      w_case(9.99999999999999980e-13_wp, 1.50000000000000007e-12_wp, 1.24999999999999995e-24_wp, &
             1.00000000000000000e+00_wp, 1.56290257560384766e+11_wp), &
      w_case(9.99999999999999980e-13_wp, 7.07106781186547573e-01_wp, 5.00000000000000000e-01_wp, &
             5.00000000000000000e-01_wp, 4.20158387512467757e-01_wp), &
      w_case(9.99999999999999980e-13_wp, 9.99999499999875030e-01_wp, 9.99998999999999971e-01_wp, &
             9.99999999999999955e-07_wp, 2.50000249999331126e-01_wp), &
      w_case(9.99999999999999980e-13_wp, 1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, &
             9.99999999999999945e-21_wp, 2.50000000000000000e-01_wp), &
      w_case(9.99999999999999980e-13_wp, 1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, &
             9.99999999999999929e-41_wp, 2.50000000000000000e-01_wp), &
      w_case(9.99999999999999980e-13_wp, 1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, &
             0.00000000000000000e+00_wp, 2.50000000000000000e-01_wp), &
      w_case(9.99999999999999955e-07_wp, 1.00000000000000017e-06_wp, 2.00000000000000017e-28_wp, &
             9.99999999999000022e-01_wp, 1.96349540849263896e+05_wp), &
      w_case(9.99999999999999955e-07_wp, 1.00000000999999999e-06_wp, 2.00000000999999992e-20_wp, &
             9.99999999999000022e-01_wp, 1.96349539867516200e+05_wp), &
      w_case(9.99999999999999955e-07_wp, 1.00100000000000003e-06_wp, 2.00099999999999997e-15_wp, &
             9.99999999998998024e-01_wp, 1.96251409014964302e+05_wp), &
      w_case(9.99999999999999955e-07_wp, 1.50000000000000004e-06_wp, 1.24999999999999992e-12_wp, &
             9.99999999997750022e-01_wp, 1.56290257560260216e+05_wp), &
      w_case(9.99999999999999955e-07_wp, 7.07106781186547573e-01_wp, 4.99999999999000022e-01_wp, &
             5.00000000000000000e-01_wp, 4.20158387493971830e-01_wp), &
      w_case(9.99999999999999955e-07_wp, 9.99999499999875030e-01_wp, 9.99998999998999993e-01_wp, &
             9.99999999999999955e-07_wp, 2.50000249992576806e-01_wp), &
      w_case(9.99999999999999955e-07_wp, 1.00000000000000000e+00_wp, 9.99999999999000022e-01_wp, &
             9.99999999999999945e-21_wp, 2.49999999993245681e-01_wp), &
      w_case(9.99999999999999955e-07_wp, 1.00000000000000000e+00_wp, 9.99999999999000022e-01_wp, &
             9.99999999999999929e-41_wp, 2.49999999993245681e-01_wp), &
      w_case(9.99999999999999955e-07_wp, 1.00000000000000000e+00_wp, 9.99999999999000022e-01_wp, &
             0.00000000000000000e+00_wp, 2.49999999993245681e-01_wp), &
      w_case(1.00000000000000002e-03_wp, 1.00000000000000002e-03_wp, 2.00000000000000010e-22_wp, &
             9.99998999999999971e-01_wp, 1.96349442674567115e+02_wp), &
      w_case(1.00000000000000002e-03_wp, 1.00000000999999998e-03_wp, 2.00000001000000000e-14_wp, &
             9.99998999999979987e-01_wp, 1.96349441692818914e+02_wp), &
      w_case(1.00000000000000002e-03_wp, 1.00099999999999994e-03_wp, 2.00100000000000002e-09_wp, &
             9.99998997999000050e-01_wp, 1.96251310791170937e+02_wp), &
      w_case(1.00000000000000002e-03_wp, 1.50000000000000003e-03_wp, 1.25000000000000010e-06_wp, &
             9.99997750000000019e-01_wp, 1.56290133004168950e+02_wp), &
      w_case(1.00000000000000002e-03_wp, 7.07106781186547573e-01_wp, 4.99999000000000027e-01_wp, &
             5.00000000000000000e-01_wp, 4.20149660616412568e-01_wp), &
      w_case(1.00000000000000002e-03_wp, 9.99999499999875030e-01_wp, 9.99998000000000054e-01_wp, &
             9.99999999999999955e-07_wp, 2.49996949537656110e-01_wp), &
      w_case(1.00000000000000002e-03_wp, 1.00000000000000000e+00_wp, 9.99998999999999971e-01_wp, &
             9.99999999999999945e-21_wp, 2.49996699542900686e-01_wp), &
      w_case(1.00000000000000002e-03_wp, 1.00000000000000000e+00_wp, 9.99998999999999971e-01_wp, &
             9.99999999999999929e-41_wp, 2.49996699542900686e-01_wp), &
      w_case(1.00000000000000002e-03_wp, 1.00000000000000000e+00_wp, 9.99998999999999971e-01_wp, &
             0.00000000000000000e+00_wp, 2.49996699542900686e-01_wp), &
      w_case(1.00000000000000006e-01_wp, 1.00000000000000006e-01_wp, 2.00000000000000014e-18_wp, &
             9.89999999999999991e-01_wp, 1.95365326426768338e+00_wp), &
      w_case(1.00000000000000006e-01_wp, 1.00000001000000005e-01_wp, 2.00000001000000001e-10_wp, &
             9.89999999799999975e-01_wp, 1.95365325440074789e+00_wp), &
      w_case(1.00000000000000006e-01_wp, 1.00099999999999995e-01_wp, 2.00099999999999998e-05_wp, &
             9.89979990000000032e-01_wp, 1.95266699911082608e+00_wp), &
      w_case(1.00000000000000006e-01_wp, 1.49999999999999994e-01_wp, 1.25000000000000007e-02_wp, &
             9.77500000000000036e-01_wp, 1.55039496241823160e+00_wp), &
      w_case(1.00000000000000006e-01_wp, 7.07106781186547573e-01_wp, 4.89999999999999991e-01_wp, &
             5.00000000000000000e-01_wp, 3.97100331554137820e-01_wp), &
      w_case(1.00000000000000006e-01_wp, 9.99999499999875030e-01_wp, 9.89998999999999962e-01_wp, &
             9.99999999999999955e-07_wp, 2.39834841583527386e-01_wp), &
      w_case(1.00000000000000006e-01_wp, 1.00000000000000000e+00_wp, 9.89999999999999991e-01_wp, &
             9.99999999999999945e-21_wp, 2.39834603232305821e-01_wp), &
      w_case(1.00000000000000006e-01_wp, 1.00000000000000000e+00_wp, 9.89999999999999991e-01_wp, &
             9.99999999999999929e-41_wp, 2.39834603232305821e-01_wp), &
      w_case(1.00000000000000006e-01_wp, 1.00000000000000000e+00_wp, 9.89999999999999991e-01_wp, &
             0.00000000000000000e+00_wp, 2.39834603232305821e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 5.00000000000000000e-01_wp, 5.00000000000000051e-17_wp, &
             7.50000000000000000e-01_wp, 3.40087380793915872e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 5.00000004999999970e-01_wp, 5.00000002499999970e-09_wp, &
             7.49999995000000030e-01_wp, 3.40087378526666650e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 5.00499999999999945e-01_wp, 5.00250000000000044e-04_wp, &
             7.49499750000000020e-01_wp, 3.39860731416873674e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 7.50000000000000000e-01_wp, 3.12500000000000000e-01_wp, &
             4.37500000000000000e-01_wp, 2.41908172425444434e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 7.07106781186547573e-01_wp, 2.50000000000000000e-01_wp, &
             5.00000000000000000e-01_wp, 2.57012118446663496e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 9.99999499999875030e-01_wp, 7.49998999999999971e-01_wp, &
             9.99999999999999955e-07_wp, 1.58646657850802675e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 1.00000000000000000e+00_wp, 7.50000000000000000e-01_wp, &
             9.99999999999999945e-21_wp, 1.58646473366215846e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 1.00000000000000000e+00_wp, 7.50000000000000000e-01_wp, &
             9.99999999999999929e-41_wp, 1.58646473366215846e-01_wp), &
      w_case(5.00000000000000000e-01_wp, 1.00000000000000000e+00_wp, 7.50000000000000000e-01_wp, &
             0.00000000000000000e+00_wp, 1.58646473366215846e-01_wp), &
      w_case(9.00000000000000022e-01_wp, 9.00000000000000133e-01_wp, 1.62000000000000019e-16_wp, &
             1.89999999999999836e-01_wp, 9.50964229081089352e-02_wp), &
      w_case(9.00000000000000022e-01_wp, 9.00000008999999990e-01_wp, 1.62000000810000000e-08_wp, &
             1.89999983799999911e-01_wp, 9.50964204055714940e-02_wp), &
      w_case(9.00000000000000022e-01_wp, 9.00900000000000034e-01_wp, 1.62081000000000009e-03_wp, &
             1.88379190000000002e-01_wp, 9.48459443478566339e-02_wp), &
      w_case(9.00000000000000022e-01_wp, 9.99999499999875030e-01_wp, 1.89999000000000001e-01_wp, &
             9.99999999999999955e-07_wp, 6.16132750126763898e-02_wp), &
      w_case(9.00000000000000022e-01_wp, 1.00000000000000000e+00_wp, 1.90000000000000002e-01_wp, &
             9.99999999999999945e-21_wp, 6.16130246776680698e-02_wp), &
      w_case(9.00000000000000022e-01_wp, 1.00000000000000000e+00_wp, 1.90000000000000002e-01_wp, &
             9.99999999999999929e-41_wp, 6.16130246776680698e-02_wp), &
      w_case(9.00000000000000022e-01_wp, 1.00000000000000000e+00_wp, 1.90000000000000002e-01_wp, &
             0.00000000000000000e+00_wp, 6.16130246776680698e-02_wp), &
      w_case(9.98999999999999999e-01_wp, 9.99000000000000110e-01_wp, 1.99600200000000017e-16_wp, &
             1.99899999999980042e-03_wp, 8.78761049521700581e-03_wp), &
      w_case(9.98999999999999999e-01_wp, 9.99000009990000049e-01_wp, 1.99600200998000997e-08_wp, &
             1.99898003997990006e-03_wp, 8.78758851516678319e-03_wp), &
      w_case(9.98999999999999999e-01_wp, 9.99998999999999971e-01_wp, 1.99700000100000007e-03_wp, &
             1.99999900000000009e-06_wp, 5.96922519495062150e-03_wp), &
      w_case(9.98999999999999999e-01_wp, 9.99999499999875030e-01_wp, 1.99800000000000021e-03_wp, &
             9.99999999999999955e-07_wp, 5.96699901738271740e-03_wp), &
      w_case(9.98999999999999999e-01_wp, 1.00000000000000000e+00_wp, 1.99899999999999991e-03_wp, &
             9.99999999999999945e-21_wp, 5.96476523533458983e-03_wp), &
      w_case(9.98999999999999999e-01_wp, 1.00000000000000000e+00_wp, 1.99899999999999991e-03_wp, &
             9.99999999999999929e-41_wp, 5.96476523533458983e-03_wp), &
      w_case(9.98999999999999999e-01_wp, 1.00000000000000000e+00_wp, 1.99899999999999991e-03_wp, &
             0.00000000000000000e+00_wp, 5.96476523533458983e-03_wp), &
      w_case(9.99999999499999959e-01_wp, 1.00000000000000000e+00_wp, 1.00000000000000006e-09_wp, &
             0.00000000000000000e+00_wp, 4.21637021476251657e-06_wp), &
      w_case(9.99999999499999959e-01_wp, 9.99999999999999445e-01_wp, 9.99998999999999950e-10_wp, &
             1.00000000000000008e-15_wp, 4.21637337701444220e-06_wp), &
      w_case(9.99999999499999959e-01_wp, 9.99999999749999979e-01_wp, 5.00000000000000031e-10_wp, &
             5.00000000000000031e-10_wp, 5.35824602493022755e-06_wp), &
      w_case(9.99999999499999959e-01_wp, 9.99999999500000514e-01_wp, 1.00000000000000008e-15_wp, &
             9.99998999999999950e-10_wp, 6.20911611694746056e-06_wp), &
      w_case(1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, 1.00000000000000007e-17_wp, &
             0.00000000000000000e+00_wp, 4.21637021355783936e-10_wp), &
      w_case(1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, 9.99998999999999943e-18_wp, &
             9.99999999999999960e-24_wp, 4.21637337580976311e-10_wp), &
      w_case(1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, 5.00000000000000036e-18_wp, &
             5.00000000000000036e-18_wp, 5.35824602289267773e-10_wp), &
      w_case(1.00000000000000000e+00_wp, 1.00000000000000000e+00_wp, 9.99999999999999960e-24_wp, &
             9.99998999999999943e-18_wp, 6.20911611384290390e-10_wp)]

   type(ia_case), parameter :: ia_ref(*) = [ &
      ia_case(1.00000000000000000e+00_wp, 1.00000000000000007e-17_wp, 4.21637021355783964e-44_wp), &
      ia_case(9.99999999499999959e-01_wp, 1.00000000000000006e-09_wp, 4.21637021476251724e-24_wp), &
      ia_case(9.99499874937460953e-01_wp, 1.00000000000000002e-03_wp, 4.21757549346561442e-09_wp), &
      ia_case(9.74679434480896445e-01_wp, 5.00000000000000028e-02_wp, 7.56278482071808835e-05_wp), &
      ia_case(9.48683298050513768e-01_wp, 1.00000000000000006e-01_wp, 4.34325285859868762e-04_wp), &
      ia_case(8.36660026534075563e-01_wp, 2.99999999999999989e-01_wp, 7.23988431355147757e-03_wp), &
      ia_case(7.07106781186547573e-01_wp, 5.00000000000000000e-01_wp, 2.81703969602710644e-02_wp), &
      ia_case(5.47722557505166074e-01_wp, 6.99999999999999956e-01_wp, 7.26612595431842395e-02_wp), &
      ia_case(1.00000000000000006e-01_wp, 9.89999999999999991e-01_wp, 2.35061894627982937e-01_wp), &
      ia_case(1.00000000000000002e-03_wp, 9.99998999999999971e-01_wp, 2.49996199549751580e-01_wp), &
      ia_case(9.99999999999999955e-07_wp, 9.99999999999000022e-01_wp, 2.49999999992745664e-01_wp), &
      ia_case(9.99999999999999980e-13_wp, 1.00000000000000000e+00_wp, 2.50000000000000000e-01_wp)]

contains

   !> Collect all tests of the elliptic suite.
   subroutine collect_elliptic(testsuite)
      !> the tests
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("mpmath_w", test_mpmath_w), &
         new_unittest("mpmath_ia", test_mpmath_ia), &
         new_unittest("quadrature", test_quadrature), &
         new_unittest("c_equals_one", test_c_equals_one), &
         new_unittest("c_to_a_limit", test_c_to_a_limit), &
         new_unittest("extremes_finite", test_extremes_finite), &
         new_unittest("invalid_input", test_invalid_input), &
         new_unittest("a_to_zero_limit", test_a_to_zero), &
         new_unittest("carlson_form_agrees", test_carlson)]
   end subroutine collect_elliptic

   !> istar_scaled against the mpmath table, relative error <= 5e-15.
   subroutine test_mpmath_w(error)
      type(error_type), allocatable, intent(out) :: error
      type(w_case) :: r
      integer :: i
      do i = 1, size(w_ref)
         r = w_ref(i)
         call check_close(error, istar_scaled(r%a, r%c, r%d2, r%omc2), r%w, rtol_ref, &
            what=label("W", [r%a, r%c, r%omc2]))
      end do
   end subroutine test_mpmath_w

   !> ia_star against the mpmath table, relative error <= 5e-15.
   subroutine test_mpmath_ia(error)
      type(error_type), allocatable, intent(out) :: error
      type(ia_case) :: r
      integer :: i
      do i = 1, size(ia_ref)
         r = ia_ref(i)
         call check_close(error, ia_star(r%a, r%oma2), r%ia, rtol_ref, &
            what=label("I_A*", [r%a, r%oma2]))
      end do
   end subroutine test_mpmath_ia

   !> The closed form against tanh-sinh quadrature of the phi-form, <= 1e-13.
   subroutine test_quadrature(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: a(*) = [1.0e-12_wp, 1.0e-6_wp, 1.0e-3_wp, 0.1_wp, 0.3_wp, &
         0.5_wp, 0.9_wp, 0.999_wp, 0.99999999_wp]
      real(wp), parameter :: s(*) = [1.0e-7_wp, 1.0e-3_wp, 0.3_wp, 0.9_wp, 0.999999_wp, 1.0_wp]
      real(wp) :: c, wq
      integer :: i, j, status
      do i = 1, size(a)
         do j = 1, size(s)
            c = a(i) + s(j)*(1.0_wp - a(i))
            if (.not. c > a(i)) cycle
            call istar_quadrature(a(i), c, wq, status)
            call check(error, status == wa_ok, label("quadrature status", [a(i), c]))
            call check_close(error, istar_scaled(a(i), c, (c - a(i))*(c + a(i)), &
               (1.0_wp - c)*(1.0_wp + c)), wq, rtol_quad, what=label("W vs quadrature", [a(i), c]))
         end do
      end do
   end subroutine test_quadrature

   !> W(A,1) = I_A*/(1-A^2)^2 (2.28c): ia_star against istar_scaled at 1-C^2 = 0 (which
   !> uses I_A*) and at 1-C^2 = 1e-19 (1-A^2), where the closed form (E2) is used and W
   !> differs from W(A,1) by O(1e-19).
   subroutine test_c_equals_one(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: oma2(*) = [1.0e-17_wp, 1.0e-9_wp, 1.0e-3_wp, 0.05_wp, 0.3_wp, &
         0.75_wp, 0.99_wp, 0.999999999999_wp]
      real(wp) :: a, expected, omc2
      integer :: i
      do i = 1, size(oma2)
         a = sqrt(1.0_wp - oma2(i))
         expected = ia_star(a, oma2(i))/oma2(i)**2
         call check_close(error, istar_scaled(a, 1.0_wp, oma2(i), 0.0_wp), expected, &
            rtol_pair, what=label("W(A,1)", [a, oma2(i)]))
         omc2 = 1.0e-19_wp*oma2(i)
         call check_close(error, istar_scaled(a, sqrt(1.0_wp - omc2), oma2(i) - omc2, omc2), &
            expected, rtol_pair, what=label("W(A,1-) vs I_A*", [a, oma2(i)]))
      end do
   end subroutine test_c_equals_one

   !> W -> pi sqrt(1-A^2)/(16A) as C -> A: exact at d2 = 0, and within the first-order
   !> change d2 (1/A^2 + 1/(1-A^2)) for C = A(1 + eps).
   subroutine test_c_to_a_limit(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: a(*) = [1.0e-12_wp, 1.0e-6_wp, 0.3_wp, 0.9_wp, 0.99999_wp]
      real(wp), parameter :: eps(*) = [1.0e-16_wp, 1.0e-13_wp, 1.0e-10_wp]
      real(wp) :: limit, oma2, c, d2, tol
      integer :: i, j
      do i = 1, size(a)
         oma2 = (1.0_wp - a(i))*(1.0_wp + a(i))
         limit = pi*sqrt(oma2)/(16.0_wp*a(i))
         call check_close(error, istar_scaled(a(i), a(i), 0.0_wp, oma2), limit, rtol_ref, &
            what=label("W(A,A)", [a(i)]))
         do j = 1, size(eps)
            c = a(i)*(1.0_wp + eps(j))
            d2 = (c - a(i))*(c + a(i))
            tol = rtol_ref + d2*(1.0_wp/a(i)**2 + 1.0_wp/oma2)
            call check_close(error, istar_scaled(a(i), c, d2, oma2 - d2), limit, tol, &
               what=label("W(A,A+)", [a(i), eps(j)]))
         end do
      end do
   end subroutine test_c_to_a_limit

   !> Finite, positive values over a grid reaching A = 1e-150, 1-A^2 = 1e-17, C = 1 and
   !> C - A = 1e-16 A, with the inputs formed as in wa_dw (no cancellation).
   subroutine test_extremes_finite(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: oma(*) = [1.0_wp - 1.0e-150_wp, 1.0_wp - 1.0e-12_wp, 0.5_wp, &
         1.0e-3_wp, 1.0e-8_wp, 5.0e-18_wp]                       ! 1 - A
      real(wp), parameter :: s(*) = [0.0_wp, 1.0e-16_wp, 1.0e-8_wp, 0.5_wp, &
         1.0_wp - 1.0e-12_wp, 1.0_wp - 1.0e-30_wp, 1.0_wp]       ! (C-A)/(1-A)
      real(wp) :: a, c, d, w, ia
      integer :: i, j
      do i = 1, size(oma)
         a = max(1.0_wp - oma(i), 1.0e-150_wp)
         if (i == 1) a = 1.0e-150_wp
         ia = ia_star(a, oma(i)*(2.0_wp - oma(i)))
         call check(error, ieee_is_finite(ia) .and. ia >= 0.0_wp, label("I_A* finite", [a]))
         do j = 1, size(s)
            d = s(j)*oma(i)
            c = a + d
            w = istar_scaled(a, c, d*(2.0_wp*a + d), (1.0_wp - s(j))*oma(i)*(1.0_wp + c))
            call check(error, ieee_is_finite(w) .and. w > 0.0_wp, label("W finite", [a, s(j)]))
         end do
      end do
   end subroutine test_extremes_finite

   !> NaN (elemental functions) or wa_invalid_argument (quadrature) outside the domain.
   subroutine test_invalid_input(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: nan, w
      integer :: status
      nan = ieee_value(nan, ieee_quiet_nan)
      call check(error, ieee_is_nan(istar_scaled(0.0_wp, 1.0e-101_wp, 1.0e-202_wp, 1.0_wp)), &
         "W at A = 0, C < 1e-100")
      call check(error, ieee_is_nan(istar_scaled(0.5_wp, 1.5_wp, 2.0_wp, -1.25_wp)), "W at C > 1")
      call check(error, ieee_is_nan(istar_scaled(0.5_wp, 0.4_wp, -0.09_wp, 0.84_wp)), "W at C < A")
      call check(error, ieee_is_nan(istar_scaled(0.5_wp, 1.0_wp, 0.0_wp, 0.0_wp)), "W at A^2 = 1")
      call check(error, ieee_is_nan(istar_scaled(nan, 0.5_wp, 0.25_wp, 0.75_wp)), "W at NaN")
      call check(error, ieee_is_nan(ia_star(1.5_wp, 0.1_wp)), "I_A* at A > 1")
      call check(error, ieee_is_nan(ia_star(0.5_wp, -0.1_wp)), "I_A* at 1-A^2 < 0")
      call istar_quadrature(0.5_wp, 0.4_wp, w, status)
      call check(error, status == wa_invalid_argument .and. ieee_is_nan(w), "quadrature at C < A")
   end subroutine test_invalid_input

   !> W(0,C) (the a* -> 0 limit, closed form and series) against mpmath quadrature of
   !> int_0^C X sqrt(1-X^2) sqrt(C^2-X^2) dX / C^4 (40 digits), and continuity with the
   !> AGM form: W(A,C) -> W(0,C) as A -> 0 (A = 1e-150 is the AGM's smallest A).
   subroutine test_a_to_zero(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: c(4) = [1.0e-5_wp, 0.1_wp, 0.5_wp, 0.9_wp]
      real(wp), parameter :: w_ref(4) = [33333.33333266666666665714_wp, &
         3.326657110966029273655508_wp, 0.6320305876241882985901746_wp, &
         0.3002310768987284235819305_wp]
      integer :: i
      do i = 1, size(c)
         call check_close(error, istar_scaled(0.0_wp, c(i), c(i)**2, (1.0_wp - c(i))*(1.0_wp + c(i))), &
            w_ref(i), 2.0e-15_wp, what="W(0,C)")
         if (allocated(error)) return
         call check_close(error, istar_scaled(1.0e-150_wp, c(i), c(i)**2, &
            (1.0_wp - c(i))*(1.0_wp + c(i))), w_ref(i), 2.0e-15_wp, what="W(1e-150,C)")
         if (allocated(error)) return
      end do
      call check_close(error, istar_scaled(0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp), 0.25_wp, 1.0e-16_wp, &
         what="W(0,1) = I_A*(0) = 1/4")
   end subroutine test_a_to_zero

   !> "name(x1, x2, ...)" for failure messages.
   pure function label(name, x) result(text)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: x(:)
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      integer :: i
      text = name//"("
      do i = 1, size(x)
         write (buffer, '(es24.16)') x(i)
         text = text//trim(adjustl(buffer))//merge(", ", ") ", i < size(x))
      end do
   end function label

   !> The textbook Carlson form (GSL R_F, R_D, R_J) agrees where it does not cancel badly.
   subroutine test_carlson(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: as(4) = [0.1_wp, 0.3_wp, 0.5_wp, 0.9_wp]
      real(wp), parameter :: cs(4) = [0.3_wp, 0.7_wp, 0.7_wp, 0.95_wp]
      real(wp) :: w
      integer :: i, status
      do i = 1, size(as)
         call istar_carlson(as(i), cs(i), (cs(i) - as(i))*(cs(i) + as(i)), &
            (1 - cs(i))*(1 + cs(i)), w, status)
         call check(error, status == wa_ok, "istar_carlson status")
         call check_close(error, w, istar_scaled(as(i), cs(i), (cs(i) - as(i))*(cs(i) + as(i)), &
            (1 - cs(i))*(1 + cs(i))), 1.0e-12_wp, what="Carlson vs AGM")
      end do
      call istar_carlson(0.5_wp, 0.4_wp, -0.09_wp, 0.84_wp, w, status)
      call check(error, status == wa_invalid_argument, "C < A rejected")
   end subroutine test_carlson

end module test_elliptic
