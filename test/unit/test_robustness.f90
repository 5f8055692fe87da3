!> Regression tests for the robustness issue (9): every reproducer found by the contract
!> fuzzer gives a correct result or a documented status, and nothing hangs.
module test_robustness
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wavyadhesion
   use wa_kinds, only: wp, pi
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_robustness

contains

   subroutine collect_robustness(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("parameter_domain", test_domain), &
         new_unittest("md_huge_mu_is_jkr_or_refused", test_md_huge_mu), &
         new_unittest("dw_a_star_zero_limit", test_dw_a_zero), &
         new_unittest("dw_mu_zero_is_westergaard", test_dw_mu_zero), &
         new_unittest("md_mechanism_change_windows", test_md_windows), &
         new_unittest("dw_roots_tiny_alpha", test_dw_roots_tiny_alpha), &
         new_unittest("dw_trace_large_mu", test_dw_trace_large_mu), &
         new_unittest("dw_shallow_corner_minimum", test_dw_shallow_corner), &
         new_unittest("dw_case1_root_born_at_a_start", test_dw_root_at_start), &
         new_unittest("md_huge_sigma0_no_c_star_blame", test_md_no_c_star_blame)]
   end subroutine collect_robustness

   type(params_type) function params_of(alpha, mu) result(params)
      real(wp), intent(in) :: alpha, mu
      integer :: status
      call new_params(alpha, mu, params, status)
   end function params_of

   !> Outside alpha in [1e-12, 1e12], mu = 0 or [1e-100, 1e100]: wa_invalid_argument
   !> (formerly NaN or -Inf with wa_ok at alpha = 1e300, 1e155, c* > 1/2 at mu = 1e-310).
   subroutine test_domain(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      real(wp), parameter :: alphas(3) = [1.0e300_wp, 1.0e155_wp, 1.0e13_wp]
      real(wp), parameter :: mus(3) = [1.0e-310_wp, 1.0e-101_wp, 1.0e200_wp]
      integer :: i, status
      do i = 1, size(alphas)
         call new_params(alphas(i), 1.0_wp, p, status)
         call check(error, status == wa_invalid_argument, "huge alpha refused")
         call new_params(0.3_wp, mus(i), p, status)
         call check(error, status == wa_invalid_argument, "mu outside the domain refused")
      end do
   end subroutine test_domain

   !> MD at mu = 1e100 (the largest accepted) equals JKR to 1e-13 (the Dugdale zone is
   !> ~1e-100 wide); mu = 1e200 (which hung in the root scan) is refused.
   subroutine test_md_huge_mu(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: alphas(3) = [1.0e-8_wp, 0.3_wp, 10.0_wp]
      type(state_type) :: s
      integer :: i, status
      do i = 1, size(alphas)
         call md_equilibrium(params_of(alphas(i), 1.0e100_wp), 0.3_wp, s, status)
         call check(error, status == wa_ok, "md at mu = 1e100")
         call check_close(error, s%p_star, jkr_load(alphas(i), 0.3_wp), 1.0e-13_wp, &
            1.0e-13_wp, what="md P* = JKR at mu = 1e100")
      end do
   end subroutine test_md_huge_mu

   !> a* = 0 and a* < 1e-150 give the a* -> 0 limit of the case-1 state (formerly c* = 1/2
   !> with a wrong load, and 47 roots): mpmath root of (2.25b) with A = 0,
   !> 8 I*(0,C) = (1+C^2) C - (1-C^2)^2 artanh C, at alpha = 0.3, mu = 1.
   subroutine test_dw_a_zero(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: c_ref = 0.1304603380892495430681232_wp
      real(wp), parameter :: p_ref = -0.08835236292906315510364877_wp
      real(wp), parameter :: as(3) = [0.0_wp, 1.0e-200_wp, 1.0e-160_wp]
      type(state_type) :: s, states(8)
      integer :: i, n, status
      do i = 1, size(as)
         call dw_equilibrium(params_of(0.3_wp, 1.0_wp), as(i), s, status)
         call check(error, status == wa_ok .and. s%zone_case == zone_inside, "dw a* -> 0")
         call check_close(error, s%c_star, c_ref, 1.0e-14_wp, what="c* at a* -> 0")
         call check_close(error, s%p_star, p_ref, 1.0e-14_wp, what="P* at a* -> 0")
         call dw_roots(params_of(0.3_wp, 1.0_wp), as(i), states, n, status)
         call check(error, status == wa_ok .and. n == 1, "one DW state at a* -> 0")
      end do
   end subroutine test_dw_a_zero

   !> mu = 0 is the Westergaard limit for DW too: the branch, the load path and the critical
   !> forces equal Westergaard's (formerly "step size underflow on the case-1 curve").
   subroutine test_dw_mu_zero(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      real(wp) :: fc, pf, fc_w, pf_w
      integer :: status
      call trace_branch(model_dw, params_of(0.3_wp, 0.0_wp), b, status)
      call check(error, status == wa_ok .and. b%n > 2, "dw branch at mu = 0")
      if (allocated(error)) return
      call check(error, all(abs(b%p_star(1:b%n) - sin(pi*b%a_star(1:b%n))**2) <= 1.0e-15_wp), &
         "dw branch at mu = 0 is P* = sin^2(pi a*)")
      call critical_forces(model_dw, params_of(0.3_wp, 0.0_wp), fc, pf, status)
      call critical_forces(model_westergaard, params_of(0.3_wp, 0.0_wp), fc_w, pf_w, status)
      call check(error, status == wa_ok .and. fc == fc_w .and. pf == pf_w, &
         "dw critical forces at mu = 0 are Westergaard's")
   end subroutine test_dw_mu_zero

   !> Where the MD pull-off mechanism changes, a case-1 root at c* = 1/2 - 1e-7 and the
   !> case-2 state coexist at a* -> 0; the tracer took one for the other and found "no piece
   !> of the curve reaches a* = 1/2". Each window now gives finite forces that join their
   !> neighbours at +-1e-6 relative in mu.
   subroutine test_md_windows(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: alphas(4) = [1.0_wp, 1.0_wp, 0.3_wp, 3.0_wp]
      real(wp), parameter :: mus(4) = [0.79369860901363931_wp, 0.7936921_wp, &
         0.15939872014691756_wp, 3.4338367324868928_wp]
      real(wp) :: fc, pf, fc2, pf2
      integer :: i, status
      do i = 1, size(mus)
         call critical_forces(model_md, params_of(alphas(i), mus(i)), fc, pf, status)
         call check(error, status == wa_ok, "md critical forces in a mechanism-change window")
         call check(error, ieee_is_finite(fc) .and. ieee_is_finite(pf), "finite forces")
         call critical_forces(model_md, params_of(alphas(i), mus(i)*(1.0_wp + 1.0e-6_wp)), &
            fc2, pf2, status)
         call check(error, status == wa_ok .and. abs(fc2 - fc) < 1.0e-3_wp, "P_fc continuous")
      end do
   end subroutine test_md_windows

   !> dw_roots found no root where dw_equilibrium finds one (alpha ~ 2e-8: the scan began
   !> above the root, beyond the large-mu estimate's reach).
   subroutine test_dw_roots_tiny_alpha(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      type(state_type) :: s, states(8)
      integer :: n, status
      p = params_of(2.1969480238680286e-08_wp, 0.015303748132451851_wp)
      call dw_equilibrium(p, 0.14607854996624908_wp, s, status)
      call dw_roots(p, 0.14607854996624908_wp, states, n, status)
      call check(error, status == wa_ok .and. n == 1, "dw_roots finds the root")
      if (allocated(error)) return
      call check(error, states(1)%c_star == s%c_star .and. states(1)%p_star == s%p_star, &
         "dw_roots agrees with dw_equilibrium")
   end subroutine test_dw_roots_tiny_alpha

   !> DW traces up to mu = 1e6 (the zone reaches c* = 1/2 within 1e-12 of a* = 1/2) end in
   !> full contact with the pull-off at the case-2 corner, 1 - Sigma0/2; where the switch is
   !> beyond double precision (mu = 1e9) the tracer refuses with wa_numerical_error.
   subroutine test_dw_trace_large_mu(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      real(wp) :: fc, pf
      integer :: status
      p = params_of(0.3_wp, 1.0e6_wp)
      call critical_forces(model_dw, p, fc, pf, status)
      call check(error, status == wa_ok, "dw critical forces at mu = 1e6")
      call check_close(error, pf, 1.0_wp - 0.5_wp*p%sigma0, 1.0e-14_wp, what="P_pf = 1 - Sigma0/2")
      call critical_forces(model_dw, params_of(0.3_wp, 1.0e9_wp), fc, pf, status)
      call check(error, status == wa_numerical_error, "dw at mu = 1e9: clean refusal")
   end subroutine test_dw_trace_large_mu

   !> DW alpha = 0.47, mu in [0.50894, 0.50898]: P* falls along case 1 into the switch to
   !> c* = 1/2 and turns within round-off of it. The tracer dropped that turn as no fold
   !> but left the corner unmarked, so the corner counted as stable and the unloading made
   !> no progress (wa_numerical_error at 263 of 401 mu). The corner is the minimum: the
   !> pull-off is a jump from case 2 at the lowest load of the branch, until a case-1 fold
   !> takes over.
   subroutine test_dw_shallow_corner(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      type(path_type) :: path
      type(params_type) :: p
      integer :: status, j
      do j = 0, 40
         p = params_of(0.47_wp, 0.50894_wp + 1.0e-6_wp*j)
         call trace_branch(model_dw, p, b, status)
         call check(error, status == wa_ok, "branch traced")
         if (allocated(error)) return
         call path_from_branch(model_dw, p, b, path, status)
         call check(error, status == wa_ok, "load path in the shallow-corner window")
         if (allocated(error)) return
         call check(error, path%p_pf == minval(b%p_star(1:b%n)), "P_pf is the lowest load")
         ! the corner minimum gives way to a case-1 fold at mu = 0.508969
         if (j <= 20) call check(error, path%pf_mechanism == mechanism_jump_case2, &
            "pull-off from the corner")
         if (j >= 35) call check(error, path%pf_mechanism == mechanism_jump_case1, &
            "pull-off from the case-1 fold")
         if (allocated(error)) return
      end do
      ! P* rises from a case-1 fold, turns (a maximum within 1e-9 of the last traced
      ! point, or within its first 1/32) and falls into the switch, whose slope the
      ! tracer read as rising: the maximum is now located from samples, the corner is
      ! the minimum, and the pull-off lands on the rising piece and leaves from the fold
      do j = 1, 2
         p = params_of(merge(0.51_wp, 4.8802567534857494e-1_wp, j == 1), &
            merge(0.5623852_wp, 5.3269258538007114e-1_wp, j == 1))
         call trace_branch(model_dw, p, b, status)
         call check(error, status == wa_ok, "branch traced (fold before the switch)")
         if (allocated(error)) return
         call path_from_branch(model_dw, p, b, path, status)
         call check(error, status == wa_ok, "load path with a fold just before the switch")
         if (allocated(error)) return
         call check(error, path%p_pf == minval(b%p_star(1:b%n)), "P_pf is the lowest load")
         call check(error, path%pf_mechanism == mechanism_jump_case1, "pull-off from the fold")
         if (allocated(error)) return
      end do
   end subroutine test_dw_shallow_corner

   !> Where the case-1 root is born at the branch's first point (F(a_start, y_max) = 0, the
   !> map's boundary 202), its c* is 1/2 within rounding and its tangent undefined: the
   !> tracer used to halve its step to underflow (DW alpha 0.396, mu 0.41587; alpha 0.850,
   !> mu 0.91070). It now starts such a piece on case 2.
   subroutine test_dw_root_at_start(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: cases(2, 3) = reshape([3.9626886387014770e-1_wp, &
         4.1586869569991353e-1_wp, 8.5044893418026790e-1_wp, 9.1069851516227895e-1_wp, &
         3.8274944785163117e-1_wp, 3.9950729210267516e-1_wp], [2, 3])
      type(branch_type) :: b
      type(path_type) :: path
      type(params_type) :: p
      integer :: status, k
      do k = 1, size(cases, 2)
         p = params_of(cases(1, k), cases(2, k))
         call trace_branch(model_dw, p, b, status)
         call check(error, status == wa_ok, "branch traced from a root born at a_start")
         if (allocated(error)) return
         call path_from_branch(model_dw, p, b, path, status)
         call check(error, status == wa_ok, "load path")
         if (allocated(error)) return
         call check(error, b%a_star(b%n) == 0.5_wp, "the branch reaches full contact")
         if (allocated(error)) return
      end do
   end subroutine test_dw_root_at_start

   !> MD at alpha = 1.94e11, mu = 2.57e14 (Sigma0 = 8.5e21; issue 2): trace_branch,
   !> critical_forces, gap_path, gap_law and gap_critical returned wa_invalid_argument
   !> "c_star = 5.00000E-01 is outside its valid range" though no c* was passed: the crest
   !> gap's reopening (1/2 - 2.7e-24, mpmath) rounded to 1/2 - 3e-16 with a crest gap of
   !> -7e7 (the Clausen form lost every digit there) and the retry nudged c* past 1/2. Now
   !> the crest gap is exact there (test_separation, md_crest_near_half) and these give the
   !> branch's own honest status: the zone reaches c* = 1/2 within 1e-15 of a* = 1/2 (JKR limit).
   subroutine test_md_no_c_star_blame(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: p
      type(branch_type) :: br
      type(gap_path_type) :: gp
      type(gap_critical_type) :: gc
      real(wp) :: p_fc, p_pf, g(2), pa(2), pr(2), da(2), dr(2)
      integer :: st(5), k
      character(len=300) :: msg(5)
      p = params_of(194144313374.73993_wp, 256617602357780.94_wp)
      g = [0.5_wp, 2.0_wp]
      msg = ""
      call trace_branch(model_md, p, br, st(1), msg(1))
      call critical_forces(model_md, p, p_fc, p_pf, st(2), msg(2))
      call gap_path(model_md, p, gp, st(3), msg(3))
      call gap_law(model_md, p, g, pa, pr, da, dr, st(4), msg(4))
      call gap_critical(model_md, p, gc, st(5), msg(5))
      do k = 1, 5
         call check(error, st(k) == wa_numerical_error .and. index(msg(k), "c* = 1/2 closer "// &
            "than 1e-15 to a* = 1/2") > 0, "huge Sigma0: "//trim(msg(k)))
      end do
   end subroutine test_md_no_c_star_blame

end module test_robustness
