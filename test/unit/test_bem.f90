!> The smooth-adhesion (Lennard-Jones) model, src/wa_bem_*.f90: the dense symmetric
!> indefinite factorisation against matrices of known spectrum, the elastic stiffness
!> against its Fourier symbol, the law against its closed forms, and the traced model
!> against its limits (Westergaard as alpha -> 0, JKR as mu -> infinity), the grid
!> convergence at alpha 0.3, mu 3, and the prototype's snap at alpha 0.3, mu 1.
module test_bem
   use wavyadhesion
   use wa_bem_law, only: law_eval, law_potential, law_peak
   use wa_bem_path, only: lj_path_jump_start
   use wa_kinds, only: wp, pi
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_bem_dense, only: ldl_type, ldl_factor, ldl_solve
   use wa_bem_elastic, only: bem_grid_type, new_grid, stiffness_matrix
   use wa_bem_solver, only: use_two_grid, jacobian_type, factor_at, jacobian_free
   use wa_bem_elastic, only: kernel_value
   use wa_bem_fast, only: fft_plans_type, plans_create, plans_destroy, circulant_symbol, &
      circulant_apply
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_bem

contains

   subroutine collect_bem(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("ldl_inertia_and_solve", test_ldl), &
         new_unittest("stiffness_symbol", test_stiffness), &
         new_unittest("circulant_on_the_even_half", test_even_circulant), &
         new_unittest("even_circulant_rounding", test_even_circulant_rounding), &
         new_unittest("law_closed_forms", test_law), &
         new_unittest("bad_input", test_bad_input), &
         new_unittest("trace_stability_and_folds", test_trace), &
         new_unittest("prototype_snap_alpha03_mu1", test_snap), &
         new_unittest("grid_convergence_alpha03_mu3", test_convergence), &
         new_unittest("westergaard_limit", test_westergaard), &
         new_unittest("jkr_trend", test_jkr), &
         new_unittest("rigid_limit", test_rigid), &
         new_unittest("profile_means", test_profile), &
         new_unittest("state_at_a", test_state_at_a), &
         new_unittest("shifted_profile_whole_period", test_shifted), &
         new_unittest("two_grid_against_dense", test_two_grid), &
         new_unittest("w_star_from_energies", test_w_star_energies), &
         new_unittest("w_star_zero_and_scaled_steps", test_w_star_zero), &
         new_unittest("fc_peak_gradual_alpha03_mu1", test_fc_peak_gradual), &
         new_unittest("long_range_corner_mu001", test_long_range)]
   end subroutine collect_bem

   !> A = H diag(lambda) H (H a Householder reflector): inertia and solve.
   subroutine test_ldl(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 40
      type(ldl_type) :: fact
      real(wp) :: v(n), lam(n), h(n, n), a(n, n), x(n), b(n)
      integer :: i, k, case
      do case = 1, 3
         do i = 1, n
            v(i) = sin(1.7_wp*i + case) + 0.3_wp
            lam(i) = (-1.0_wp)**(i + case)*(0.5_wp + mod(7*i, 11))
         end do
         if (case == 3) lam(5) = -1.0e-9_wp         ! a nearly singular direction
         h = 0.0_wp
         do i = 1, n
            h(i, i) = 1.0_wp
         end do
         do k = 1, n
            h(:, k) = h(:, k) - 2.0_wp*v*v(k)/dot_product(v, v)
         end do
         do k = 1, n
            a(:, k) = matmul(h, lam*h(k, :))
         end do
         fact%a = a
         call ldl_factor(fact)
         call check(error, fact%negative == count(lam < 0.0_wp), "inertia of a known spectrum")
         if (allocated(error)) return
         x = [(cos(0.3_wp*i), i = 1, n)]
         b = matmul(a, x)
         call ldl_solve(fact, b)
         if (case < 3) then
            call check(error, maxval(abs(b - x)) < 1.0e-12_wp, "solve")
            if (allocated(error)) return
         end if
      end do
   end subroutine test_ldl

   !> The nodal stiffness applied to cos(2 pi k x) gives |k| cos(2 pi k x) (the Fourier
   !> symbol, Nyquist mode included), on the whole period and folded on the half period.
   subroutine test_stiffness(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: np = 32
      type(bem_grid_type) :: grid
      real(wp), allocatable :: kw(:, :), c(:), samples(:)
      integer :: k, status, j
      samples = [(sin(2*pi*j/np) + 0.2_wp*cos(4*pi*j/np), j = 0, np - 1)]   ! not even
      call new_grid(np, grid, status, profile=samples)
      call check(error, .not. grid%even .and. grid%n == np, "odd profile: whole period")
      if (allocated(error)) return
      allocate (kw(np, np))
      call stiffness_matrix(grid, kw)
      do k = 0, np/2
         c = cos(2*pi*k*grid%x)
         call check(error, maxval(abs(matmul(kw, c) - k*c)) < 1.0e-12_wp*np, "symbol |k|")
         if (allocated(error)) return
      end do
      call new_grid(np, grid, status)
      deallocate (kw)
      allocate (kw(grid%n, grid%n))
      call stiffness_matrix(grid, kw)
      do k = 0, np/2
         c = cos(2*pi*k*grid%x)
         call check(error, maxval(abs(matmul(kw, c)/grid%w - k*c)) < 1.0e-12_wp*np, &
            "folded symbol |k|")
         if (allocated(error)) return
      end do
      call check(error, abs(grid%fbar - 1.0_wp) < 1.0e-14_wp, "mean of 1 - cos")
   end subroutine test_stiffness

   !> The stiffness applied to an even field by the cosine transform of its half period
   !> (N/2 even: by the halfcomplex transform of the whole period; N/2 odd: FFTW's REDFT00; with
   !> and without plans) against the dense folded matrix W K of the kernel's values.
   subroutine test_even_circulant(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: sizes(4) = [8, 18, 64, 96]
      type(bem_grid_type) :: grid
      type(fft_plans_type) :: plans
      real(wp), allocatable :: kw(:, :), symbol(:), x(:), y(:), ref(:)
      integer :: i, j, np, status, pass
      do i = 1, size(sizes)
         np = sizes(i)
         call new_grid(np, grid, status)
         allocate (kw(grid%n, grid%n), symbol(0:np - 1), y(grid%n))
         call stiffness_matrix(grid, kw)
         call circulant_symbol(kernel_value(np, [(j, j = 0, np - 1)]), symbol)
         x = [(exp(-3.0_wp*grid%x(j)) + 0.1_wp*sin(7.0_wp*j), j = 1, grid%n)]
         ref = matmul(kw, x)/grid%w
         do pass = 1, 2
            if (pass == 2) call plans_create(plans, np, even=.true.)
            call circulant_apply(plans, symbol, x, y)
            call check(error, maxval(abs(y - ref)) < 1.0e-13_wp*np*maxval(abs(x)), &
               "even circulant against W K")
            if (allocated(error)) return
         end do
         call plans_destroy(plans)
         deallocate (kw, symbol, y)
      end do
   end subroutine test_even_circulant

   !> The rounding of the even circulant at N = 4096 on the profile 1 - cos(2 pi x) (an
   !> O(1) field whose image is O(1), as h - f near full contact): against the closed form
   !> lambda_0 - lambda_1 cos(2 pi x), its error stays below 10 ulps of the largest
   !> eigenvalue times |x| (0.6 measured). The classical reduction to a transform of
   !> length N/2 (cosft1) was at 997 (its odd modes are a running sum): a residual floor
   !> that stalled the LJ trace's corrector at alpha 0.01, mu 2.5.
   subroutine test_even_circulant_rounding(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: np = 4096
      type(bem_grid_type) :: grid
      type(fft_plans_type) :: plans
      real(wp), allocatable :: symbol(:), x(:), y(:), ref(:)
      real(wp) :: bound
      integer :: j, status
      call new_grid(np, grid, status)
      allocate (symbol(0:np - 1), y(grid%n))
      call circulant_symbol(kernel_value(np, [(j, j = 0, np - 1)]), symbol)
      x = 1.0_wp - cos(2*pi*grid%x)
      ref = np*(symbol(0) - symbol(1)*cos(2*pi*grid%x))
      call plans_create(plans, np, even=.true.)
      call circulant_apply(plans, symbol, x, y)
      call plans_destroy(plans)
      bound = 10*epsilon(1.0_wp)*np*maxval(abs(symbol))*maxval(abs(x))
      call check(error, maxval(abs(y - ref)) < bound, "even circulant's rounding at N = 4096")
   end subroutine test_even_circulant_rounding

   !> LJ 3-9: phi(eps) = -dgamma, sigma(eps) = 0, peak 16/(9 sqrt 3) dgamma/eps at
   !> 3^(1/6) eps, slope = central difference; eps/Delta = (4 alpha^4)^(1/3)/mu.
   subroutine test_law(error)
      type(error_type), allocatable, intent(out) :: error
      type(bem_law_type) :: law
      real(wp) :: s, d, sp, dp, sm, dm, h
      law = lj_law(0.3_wp, 3.0_wp)
      call check_close(error, law%eps, (4*0.3_wp**4)**(1.0_wp/3)/3, 1.0e-15_wp, what="eps")
      if (allocated(error)) return
      call check_close(error, law_potential(law, law%eps), -law%dgamma, 1.0e-15_wp, what="phi(eps)")
      if (allocated(error)) return
      call law_eval(law, law_peak(law), s, d)
      call check_close(error, s, 16.0_wp/(9*sqrt(3.0_wp))*law%dgamma/law%eps, 1.0e-14_wp, what="peak")
      if (allocated(error)) return
      call check(error, abs(d) < 1.0e-12_wp*s/law%eps, "slope zero at the peak")
      if (allocated(error)) return
      h = 1.3_wp*law%eps
      call law_eval(law, h, s, d)
      call law_eval(law, h*(1 + 1.0e-6_wp), sp, dp)
      call law_eval(law, h*(1 - 1.0e-6_wp), sm, dm)
      call check_close(error, d, (sp - sm)/(2.0e-6_wp*h), 1.0e-8_wp, what="slope")
      if (allocated(error)) return
      call check_close(error, s, (law_potential(law, h*(1 + 1.0e-6_wp)) - &
         law_potential(law, h*(1 - 1.0e-6_wp)))/(2.0e-6_wp*h), 1.0e-8_wp, what="dphi/dh")
   end subroutine test_law

   subroutine test_bad_input(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      integer :: status
      character(len=256) :: msg
      msg = ""
      call new_params(0.3_wp, 0.0_wp, params, status)
      call lj_problem(params, problem, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "mu") > 0, "mu = 0")
      if (allocated(error)) return
      call new_params(0.3_wp, 1.0_wp, params, status)
      call lj_problem(params, problem, status, msg, n=7)
      call check(error, status == wa_invalid_argument .and. index(msg, "n") > 0, "odd n")
      if (allocated(error)) return
      call lj_problem(params, problem, status, msg, n=32768)
      call check(error, status == wa_capacity_too_small, "memory cap")
      if (allocated(error)) return
      ! refused before the grid's arrays are allocated (2^30 points aborted under a memory
      ! limit: "Error allocating 4294967304 bytes"), odd or even
      call lj_problem(params, problem, status, msg, n=2**30)
      call check(error, status == wa_capacity_too_small .and. index(msg, "16384") > 0 .and. &
         .not. allocated(problem%grid%x), "n = 2^30: "//trim(msg))
      if (allocated(error)) return
      call lj_problem(params, problem, status, msg, n=huge(1))
      call check(error, status == wa_capacity_too_small .and. .not. allocated(problem%grid%x), &
         "n = huge: "//trim(msg))
      if (allocated(error)) return
      call new_params(0.3_wp, 30.0_wp, params, status)
      call lj_problem(params, problem, status, msg)
      call check(error, status == wa_capacity_too_small .and. index(msg, "2048") > 0, &
         "automatic grid cap: "//trim(msg))
      if (allocated(error)) return
      ! a range beyond 1e5 Delta is refused (the fuzzer's alpha 5.5e7, mu 4.8e-5: eps =
      ! 6.9e14 Delta, the profile lost in the far gaps' rounding gave a load of -1843 from
      ! noise); alpha 10, mu 0.01 (eps = 3420) stays in
      call new_params(5.5e7_wp, 4.8e-5_wp, params, status)
      call lj_problem(params, problem, status, msg, n=16)
      call check(error, status == wa_capacity_too_small .and. index(msg, "range") > 0 .and. &
         index(msg, "mu") > 0, "range cap: "//trim(msg))
      if (allocated(error)) return
      call new_params(10.0_wp, 0.01_wp, params, status)
      call lj_problem(params, problem, status, msg, n=64)
      call check(error, status == wa_ok, "alpha 10, mu 0.01: "//trim(msg))
      if (allocated(error)) return
      ! n_max raises the automatic grid's cap (alpha 0.3, mu 10 needs N = 8192), a zone
      ! beyond it is refused naming the N it needs (mu 30: 65536), and n_max outside
      ! [128, 16384] is refused naming n_max
      call new_params(0.3_wp, 10.0_wp, params, status)
      call lj_problem(params, problem, status, msg)
      call check(error, status == wa_capacity_too_small .and. index(msg, "N = 8192") > 0 &
         .and. index(msg, "cap of 2048") > 0, "default cap: "//trim(msg))
      if (allocated(error)) return
      call check(error, lj_auto_n(params) == 0 .and. lj_auto_n(params, 16384) == 8192, &
         "lj_auto_n with a cap")
      if (allocated(error)) return
      call lj_problem(params, problem, status, msg, n_max=16384)
      call check(error, status == wa_ok .and. problem%grid%n_period == 8192, "n_max 16384")
      if (allocated(error)) return
      call new_params(0.3_wp, 30.0_wp, params, status)
      call lj_problem(params, problem, status, msg, n_max=16384)
      call check(error, status == wa_capacity_too_small .and. index(msg, "N = 65536") > 0 &
         .and. index(msg, "cap of 16384") > 0, "beyond the cap: "//trim(msg))
      if (allocated(error)) return
      call lj_problem(params, problem, status, msg, n_max=100)
      call check(error, status == wa_invalid_argument .and. index(msg, "n_max") > 0, &
         "n_max below 128")
      if (allocated(error)) return
      call lj_problem(params, problem, status, msg, n_max=32768)
      call check(error, status == wa_invalid_argument .and. index(msg, "n_max") > 0, &
         "n_max above 16384")
   end subroutine test_bad_input

   !> Far apart: unstable under load control, stable under gap control; the end: stable
   !> under both in full contact; the inertia changes by one across each fold of its
   !> control and nowhere else; s increases.
   subroutine test_trace(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      integer :: status, i, last_load, last_gap
      call new_params(0.3_wp, 3.0_wp, params, status)
      call lj_problem(params, problem, status, n=256)
      call lj_trace(problem, br, status)
      call check(error, status == wa_ok, "trace")
      if (allocated(error)) return
      call check(error, br%neg_load(1) == 1 .and. br%neg_gap(1) == 0, "far apart")
      if (allocated(error)) return
      call check(error, br%neg_load(br%n) == 0 .and. br%neg_gap(br%n) == 0 .and. &
         br%a_star(br%n) == 0.5_wp .and. br%p_star(br%n) > 0.0_wp, "end in full contact")
      if (allocated(error)) return
      call check(error, all(br%s(2:br%n) > br%s(1:br%n - 1)), "arclength increases")
      if (allocated(error)) return
      last_load = br%neg_load(1); last_gap = br%neg_gap(1)
      do i = 2, br%n
         if (br%extremum(i) /= 0) cycle
         if (br%neg_load(i) /= last_load) then
            call check(error, abs(br%neg_load(i) - last_load) == 1 .and. &
               any(abs(br%extremum(1:i)) == 1), "load inertia changes at a fold")
            if (allocated(error)) return
         end if
         if (br%neg_gap(i) /= last_gap) then
            call check(error, abs(br%neg_gap(i) - last_gap) == 1 .and. &
               any(abs(br%extremum(1:i)) == 2), "gap inertia changes at a fold")
            if (allocated(error)) return
         end if
         last_load = br%neg_load(i); last_gap = br%neg_gap(i)
      end do
      call check(error, count(br%extremum == 1) >= 1 .and. count(br%extremum == -1) >= 1 .and. &
         count(br%extremum == 2) >= 1 .and. count(br%extremum == -2) >= 1, "folds of both kinds")
   end subroutine test_trace

   !> alpha 0.3, mu 1: loading jumps at the maximum P* = 0.3988 (the prototype's snap near
   !> 0.40; DW reaches full contact gradually at 0.78), no jump under gap control (W* = 0).
   subroutine test_snap(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: cyc
      integer :: status
      character(len=256) :: msg
      msg = ""
      call new_params(0.3_wp, 1.0_wp, params, status)
      call lj_cycle(params, cyc, status, msg)
      call check(error, status == wa_ok, "lj_cycle: "//trim(msg))
      if (allocated(error)) return
      call check(error, abs(cyc%p_snap - 0.3988_wp) < 1.0e-3_wp, "snap near 0.40")
      if (allocated(error)) return
      call check(error, cyc%p_snap_err < 1.0e-8_wp .and. cyc%p_pf_err < 1.0e-6_wp, "resolved")
      if (allocated(error)) return
      call check(error, abs(cyc%w_star) < 1.0e-10_wp .and. cyc%pf_by_jump, "no gap jump")
   end subroutine test_snap

   !> alpha 0.3, mu 3 at the automatic grid (512): P_pf* and P_fc* agree with the grid of
   !> half as many points to 1e-7 relative, the snap load (= P_fc,peak*) to 1e-4 (N = 256
   !> puts 6.5 points on the interaction zone; at 512 against 1024 it agrees to 3e-9:
   !> study/ and doc).
   subroutine test_convergence(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: cyc
      integer :: status
      character(len=256) :: msg
      msg = ""
      call new_params(0.3_wp, 3.0_wp, params, status)
      call lj_cycle(params, cyc, status, msg)
      call check(error, status == wa_ok .and. cyc%n_period == 512, "lj_cycle: "//trim(msg))
      if (allocated(error)) return
      call check(error, cyc%p_pf_err < 1.0e-7_wp*abs(cyc%p_pf) .and. &
         cyc%p_fc_err < 1.0e-7_wp*abs(cyc%p_fc) .and. cyc%p_snap_err < 1.0e-4_wp*abs(cyc%p_snap), &
         "P_pf, P_fc, snap: N and N/2 within 1e-7")
      if (allocated(error)) return
      call check(error, cyc%w_star > 0.0_wp .and. cyc%w_star_err < 1.0e-4_wp*cyc%w_star, "W*")
      if (allocated(error)) return
      ! loading snaps into full contact: the landing state has every gap within the peak
      ! tension's 3^(1/6) eps, so P_fc,peak* is the snap load (by a jump), far below P_fc*
      ! (a* = 1/2, 0.996); DW's P_fc* there is its own snap, 0.3858 (Fig. 5's comparison)
      call check(error, cyc%fc_peak_by_jump .and. cyc%p_fc_peak == cyc%p_snap .and. &
         cyc%p_fc_peak < 0.5_wp*cyc%p_fc, "P_fc,peak = the snap load")
      if (allocated(error)) return
      call check(error, abs(cyc%p_fc_peak - 0.3858_wp) < 2.0e-3_wp .and. &
         cyc%p_fc_peak_err < 1.0e-4_wp, "P_fc,peak near DW's 0.3858, resolved")
   end subroutine test_convergence

   !> alpha -> 0 at fixed mu: the stable contact states approach Westergaard's
   !> gbar* = 1 - P* + P* ln P*; the offset is of the order of the range eps and shrinks
   !> with it.
   subroutine test_westergaard(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      integer :: status, k, i
      real(wp) :: dev(2), p, alphas(2)
      character(len=256) :: msg
      alphas = [0.02_wp, 0.01_wp]
      do k = 1, 2
         call new_params(alphas(k), 1.0_wp, params, status)
         call lj_problem(params, problem, status, n=256)
         msg = ""
         call lj_trace(problem, br, status, msg)
         call check(error, status == wa_ok, "trace: "//trim(msg))
         if (allocated(error)) return
         dev(k) = 0.0_wp
         do i = 1, br%n
            p = br%p_star(i)
            if (br%stable_load(i) .and. br%stable_gap(i) .and. p > 0.05_wp .and. p < 0.9_wp) &
               dev(k) = max(dev(k), abs(br%gbar(i) - (1 - p + p*log(p)))/problem%law%eps)
         end do
         call check(error, dev(k) > 0.0_wp .and. dev(k) < 1.0_wp, "gbar* within eps of Westergaard")
         if (allocated(error)) return
         dev(k) = dev(k)*problem%law%eps
      end do
      call check(error, dev(2) < 0.5_wp*dev(1), "closer to Westergaard as alpha falls")
   end subroutine test_westergaard

   !> mu -> infinity at fixed alpha 0.3: the snap load approaches JKR's P_fc* (the maximum
   !> of sin^2 - alpha sqrt(tan), 0.38773) and P_pf* falls towards JKR's -Infinity (the
   !> fully adhered branch holds ever more tension), monotonically (mu = 0.5, 1, 3).
   subroutine test_jkr(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: cyc
      real(wp) :: jfc, jpf, pf(3), d_fc(3), mus(3)
      integer :: status, k
      mus = [0.5_wp, 1.0_wp, 3.0_wp]
      call new_params(0.3_wp, 1.0_wp, params, status)
      call critical_forces(model_jkr, params, jfc, jpf, status)
      call check(error, abs(jfc - 0.38773_wp) < 1.0e-5_wp .and. jpf < -huge(1.0_wp), "JKR")
      if (allocated(error)) return
      do k = 1, 3
         call new_params(0.3_wp, mus(k), params, status)
         call lj_cycle(params, cyc, status, estimate=.false.)
         call check(error, status == wa_ok, "lj_cycle")
         if (allocated(error)) return
         pf(k) = cyc%p_pf
         d_fc(k) = abs(cyc%p_snap - jfc)
      end do
      call check(error, pf(2) < pf(1) .and. pf(3) < pf(2), "P_pf falls with mu")
      if (allocated(error)) return
      call check(error, d_fc(2) < d_fc(1) .and. d_fc(3) < d_fc(2) .and. d_fc(3) < 2.0e-3_wp, &
         "snap towards JKR's P_fc")
   end subroutine test_jkr

   !> alpha -> 0 at fixed eps = 0.01 Delta: the pull-off approaches the rigid wave's
   !> (maximum over the crest gap of the mean LJ tension on the undeformed wave, by the
   !> trapezoidal rule, spectrally accurate for a periodic integrand), which the closed
   !> form (the parabolic crest, eps -> 0) meets to O(eps).
   subroutine test_rigid(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: cyc
      real(wp) :: alphas(2), ratio(2), rigid, mu
      integer :: k, status
      alphas = [0.003_wp, 0.001_wp]
      do k = 1, 2
         mu = (4*alphas(k)**4)**(1.0_wp/3)/0.01_wp
         call new_params(alphas(k), mu, params, status)
         call lj_cycle(params, cyc, status, n=512, estimate=.false.)
         call check(error, status == wa_ok, "lj_cycle")
         if (allocated(error)) return
         rigid = rigid_pull_off(lj_law(alphas(k), mu))
         call check(error, abs(lj_rigid_pull_off(params)/rigid - 1) < 2.0e-3_wp, &
            "closed form within O(eps) of the rigid wave")
         if (allocated(error)) return
         ratio(k) = cyc%p_pf/rigid
      end do
      call check(error, ratio(1) < ratio(2) .and. ratio(2) < 1.0_wp .and. ratio(2) > 0.999_wp, &
         "towards the rigid pull-off")
   end subroutine test_rigid

   !> -max over delta of mean sigma(delta + 1 - cos 2 pi x) (golden section).
   function rigid_pull_off(law) result(p)
      type(bem_law_type), intent(in) :: law
      real(wp) :: p, lo, hi, m1, m2
      integer :: it
      lo = 0.5_wp*law%eps; hi = 3.0_wp*law%eps
      do it = 1, 100
         m1 = lo + (hi - lo)*0.381966_wp; m2 = hi - (hi - lo)*0.381966_wp
         if (mean_tension(law, m1) > mean_tension(law, m2)) then
            hi = m2
         else
            lo = m1
         end if
      end do
      p = -mean_tension(law, 0.5_wp*(lo + hi))
   end function rigid_pull_off

   function mean_tension(law, delta) result(t)
      type(bem_law_type), intent(in) :: law
      real(wp), intent(in) :: delta
      real(wp) :: t, s(4000), d(4000)
      integer :: j
      call law_eval(law, [(delta + 1 - cos(2*pi*j/4000.0_wp), j = 0, 3999)], s, d)
      t = sum(s)/4000
   end function mean_tension

   !> The profile of a traced state: mean traction = -P*, mean gap = gbar*.
   subroutine test_profile(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      real(wp), allocatable :: x(:), gap(:), traction(:)
      integer :: status, i
      call new_params(0.3_wp, 1.0_wp, params, status)
      call lj_problem(params, problem, status, n=128)
      call lj_trace(problem, br, status)
      allocate (x(128), gap(128), traction(128))
      do i = 1, br%n, 17
         call lj_profile(problem, br%z(:, i), x, gap, traction)
         call check(error, abs(sum(traction)/128 + br%p_star(i)) < 1.0e-9_wp*(1 + abs(br%p_star(i))) &
            .and. abs(sum(gap)/128 - br%gbar(i)) < 1.0e-12_wp*br%gbar(i), "means")
         if (allocated(error)) return
      end do
   end subroutine test_profile

   !> lj_state_at_a against the traced curve: the state is the load-stable point with a*
   !> nearest the target (the rule recomputed here), its fields the lj_profile of that
   !> point from x* = -1/2 with the traction's sign turned (compressive positive); a_star
   !> outside [0, 1/2] or NaN is refused before any trace.
   subroutine test_state_at_a(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      type(lj_state_type) :: st
      real(wp), allocatable :: x(:), gap(:), traction(:)
      real(wp) :: targets(4), bad(4), miss, nan
      character(len=256) :: msg
      integer :: status, i, k, t, best, j
      targets = [0.0_wp, 0.13_wp, 0.3_wp, 0.5_wp]
      call new_params(0.3_wp, 1.0_wp, params, status)
      call lj_problem(params, problem, status, n=64)
      call lj_trace(problem, br, status)
      allocate (x(64), gap(64), traction(64))
      do t = 1, size(targets)
         call lj_state_at_a(problem, targets(t), st, status)
         call check(error, status == wa_ok .and. st%n_period == 64, "state status")
         if (allocated(error)) return
         best = 0
         miss = huge(1.0_wp)
         do k = 1, br%n
            if (br%stable_load(k) .and. abs(br%a_star(k) - targets(t)) < miss) then
               miss = abs(br%a_star(k) - targets(t))
               best = k
            end if
         end do
         call check(error, st%a_star == br%a_star(best) .and. st%p_star == br%p_star(best) &
            .and. st%b_star == br%b_star(best) .and. st%gbar == br%gbar(best) .and. &
            st%stable_load, "the nearest load-stable point")
         if (allocated(error)) return
         call lj_profile(problem, br%z(:, best), x, gap, traction)
         do i = 1, 64
            j = modulo(i - 1 + 32, 64) + 1
            call check(error, st%gap(i) == gap(j) .and. st%traction(i) == -traction(j) .and. &
               abs(st%x(i) - ((i - 1)/64.0_wp - 0.5_wp)) <= epsilon(1.0_wp), "fields")
            if (allocated(error)) return
         end do
      end do
      call check(error, st%a_star == 0.5_wp, "a* = 1/2 is full contact")
      if (allocated(error)) return
      nan = ieee_value(nan, ieee_quiet_nan)
      bad = [nan, -tiny(1.0_wp), 0.5_wp + epsilon(1.0_wp), huge(1.0_wp)]
      do t = 1, size(bad)
         msg = ""
         call lj_state_at_a(problem, bad(t), st, status, msg)
         call check(error, status == wa_invalid_argument .and. index(msg, "a_star") == 1 .and. &
            index(msg, "[0, 1/2]") > 0 .and. st%n_period == 0 .and. .not. allocated(st%x), &
            "bad a_star: "//trim(msg))
         if (allocated(error)) return
      end do
   end subroutine test_state_at_a

   !> The sinusoid sampled with a shift (not even about x = 0: solved on the whole period)
   !> gives the critical loads of the even half-period solution.
   subroutine test_shifted(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: even, shifted
      real(wp), allocatable :: samples(:)
      integer :: status, j
      character(len=256) :: msg
      msg = ""
      samples = [(1 - cos(2*pi*(j/96.0_wp - 0.1_wp)), j = 0, 95)]
      call new_params(0.3_wp, 1.0_wp, params, status)
      call lj_cycle(params, even, status, msg, n=128, estimate=.false.)
      call check(error, status == wa_ok, "even: "//trim(msg))
      if (allocated(error)) return
      call lj_cycle(params, shifted, status, msg, n=128, profile=samples, estimate=.false.)
      call check(error, status == wa_ok, "shifted: "//trim(msg))
      if (allocated(error)) return
      call check(error, abs(shifted%p_pf - even%p_pf) < 1.0e-9_wp .and. &
         abs(shifted%p_snap - even%p_snap) < 1.0e-9_wp .and. &
         abs(shifted%p_fc - even%p_fc) < 1.0e-9_wp, "shift invariance")
   end subroutine test_shifted

   !> The two-grid preconditioner (FFT products, no dense factorisation of the grid) at
   !> N = 256 over a coarse grid of 64: the inertia it counts across the folds equals
   !> that of the dense factorisation at every state that is not a fold, and the loads
   !> at the folds of P* equal the dense trace's.
   subroutine test_two_grid(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: fast, dense
      type(lj_branch_type) :: bf, bd
      type(jacobian_type) :: jac
      integer :: status, i
      real(wp), allocatable :: pf(:), pd(:)
      call new_params(0.3_wp, 3.0_wp, params, status)
      call lj_problem(params, dense, status, n=256)
      call lj_problem(params, fast, status, n=256)
      call use_two_grid(fast, 64)
      call lj_trace(fast, bf, status)
      call check(error, status == wa_ok, "two-grid trace")
      if (allocated(error)) return
      do i = 1, bf%n
         if (bf%extremum(i) /= 0) cycle
         call factor_at(dense, bf%z(:, i), jac)
         call check(error, jac%neg_load == bf%neg_load(i) .and. jac%neg_gap == bf%neg_gap(i), &
            "counted inertia against the dense factorisation")
         if (allocated(error)) exit
      end do
      call jacobian_free(jac)
      if (allocated(error)) return
      call lj_trace(dense, bd, status)
      pf = pack(bf%p_star(1:bf%n), abs(bf%extremum(1:bf%n)) == 1)
      pd = pack(bd%p_star(1:bd%n), abs(bd%extremum(1:bd%n)) == 1)
      call check(error, size(pf) >= 2 .and. size(pd) >= 2, "folds of P*")
      if (allocated(error)) return
      ! every fold of P* of the dense trace is one of the two-grid trace (P* at a fold is
      ! stationary, so the GMRES tolerance hardly shows in it; N = 256 under-resolves the
      ! zone, so a pair of lattice folds may fall inside one step of either trace)
      do i = 1, size(pd)
         call check(error, minval(abs(pf - pd(i))) < 1.0e-9_wp, "P* folds against the dense trace")
         if (allocated(error)) return
      end do
   end subroutine test_two_grid

   !> W* = -oint P* dgbar* at alpha 0.3, mu 3, N = 256 is the sum over the gap path's jumps
   !> of the energy at fixed mean gap dissipated by each: the same with the trace's step
   !> limits halved (the quadrature it replaced moved by 8e-7 there), and the library's
   !> energies against the equilibrium identity mean(u K u) = -mean((u - mean u) sigma(h))
   !> (no stiffness product; K u = -(sigma + P*) at a state).
   subroutine test_w_star_energies(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      type(lj_cycle_type) :: cyc(2)
      type(lj_trace_options) :: opts
      integer :: status, pass, k
      real(wp) :: w
      character(len=256) :: msg
      call new_params(0.3_wp, 3.0_wp, params, status)
      call lj_problem(params, problem, status, n=256)
      do pass = 1, 2
         if (pass == 2) then
            opts%max_turn = 0.5_wp*opts%max_turn
            opts%dp_max = 0.5_wp*opts%dp_max
            opts%dg_max = 0.5_wp*opts%dg_max
         end if
         msg = ""
         call lj_trace(problem, br, status, msg, opts)
         if (status == wa_ok) call lj_paths(problem, br, cyc(pass), status, msg)
         call check(error, status == wa_ok, "trace and paths: "//trim(msg))
         if (allocated(error)) return
      end do
      call check(error, abs(cyc(1)%w_star - cyc(2)%w_star) < 1.0e-12_wp, &
         "W* independent of the step limits")
      if (allocated(error)) return
      ! the branch of pass 2 with its inserted landing states: the identity's energies
      w = 0.0_wp
      do k = 1, cyc(2)%gap%n
         if (cyc(2)%gap%event(k) /= lj_path_jump_start) cycle
         w = w + energy(k) - energy(k + 1)
      end do
      call check(error, count(cyc(2)%gap%event(1:cyc(2)%gap%n) == lj_path_jump_start) == 4 &
         .and. abs(w - cyc(2)%w_star) < 1.0e-9_wp*cyc(2)%w_star, "W* against the identity")
   contains
      !> Pi of the branch state of event k of the gap path, by the equilibrium identity.
      function energy(k) result(e)
         integer, intent(in) :: k
         real(wp) :: e
         real(wp), allocatable :: u(:), sig(:), slope(:)
         integer :: i, n
         n = problem%grid%n
         i = findloc(br%gbar(1:br%n) == cyc(2)%gap%gbar(k) .and. &
            br%p_star(1:br%n) == cyc(2)%gap%p_star(k), .true., dim=1)
         allocate (u(n), sig(n), slope(n))
         call law_eval(problem%law, br%z(1:n, i), sig, slope)
         u = br%z(1:n, i) - problem%grid%f
         u = u - sum(problem%grid%w*u)/problem%grid%n_period
         e = sum(problem%grid%w*(-0.5_wp*u*sig + law_potential(problem%law, br%z(1:n, i)))) &
            /problem%grid%n_period
      end function energy
   end subroutine test_w_star_energies

   !> Cycles without a jump under gap control have W* = 0 exactly (not rounding); a
   !> long-ranged law (eps/Delta 23 at alpha 3, mu 0.3; 3400 at alpha 10, mu 0.01) is traced
   !> in steps of its own gap scale: about 100 points (1131 at alpha 3, mu 0.3 and more than
   !> max_points at alpha 10, mu 0.01 in steps of at most 0.05 in gbar*).
   subroutine test_w_star_zero(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      type(lj_cycle_type) :: cyc
      integer :: status, k
      real(wp), parameter :: cases(2, 2) = reshape([3.0_wp, 0.3_wp, 10.0_wp, 0.01_wp], [2, 2])
      character(len=256) :: msg
      do k = 1, 2
         call new_params(cases(1, k), cases(2, k), params, status)
         call lj_problem(params, problem, status, n=64)
         msg = ""
         call lj_trace(problem, br, status, msg)
         if (status == wa_ok) call lj_paths(problem, br, cyc, status, msg)
         call check(error, status == wa_ok, "trace and paths: "//trim(msg))
         if (allocated(error)) return
         call check(error, cyc%w_star == 0.0_wp .and. &
            .not. any(cyc%gap%event(1:cyc%gap%n) == lj_path_jump_start), "W* = 0, no jump")
         if (allocated(error)) return
         call check(error, br%n < 200, "points of a long-ranged law's trace")
         if (allocated(error)) return
      end do
   end subroutine test_w_star_zero

   !> alpha 0.3, mu 1: loading snaps at 0.3988 onto a state whose largest gap is still
   !> beyond 3^(1/6) eps, then rises gradually: P_fc,peak* is where the largest gap falls
   !> to it, between the traced points that bracket it (and so between the snap and
   !> P_fc*); the traced branch, walked independently here, shows that bracket.
   subroutine test_fc_peak_gradual(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: cyc
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: br
      real(wp) :: peak
      integer :: status, i
      logical :: bracketed
      character(len=256) :: msg
      msg = ""
      call new_params(0.3_wp, 1.0_wp, params, status)
      call lj_cycle(params, cyc, status, msg)
      call check(error, status == wa_ok, "lj_cycle: "//trim(msg))
      if (allocated(error)) return
      call check(error, .not. cyc%fc_peak_by_jump .and. cyc%p_fc_peak > cyc%p_snap .and. &
         cyc%p_fc_peak < cyc%p_fc .and. cyc%p_fc_peak_err < 1.0e-8_wp, "gradual, ordered")
      if (allocated(error)) return
      call lj_problem(params, problem, status, msg, n=cyc%n_period)
      call lj_trace(problem, br, status, msg)
      call check(error, status == wa_ok, "lj_trace: "//trim(msg))
      if (allocated(error)) return
      peak = law_peak(problem%law)
      bracketed = .false.
      do i = 1, br%n - 1       ! the first load-stable interval where h_max falls to the peak
         if (br%stable_load(i) .and. br%stable_load(i + 1) .and. br%h_max(i) > peak .and. &
            br%h_max(i + 1) <= peak .and. br%p_star(i) >= cyc%p_snap) then
            bracketed = cyc%p_fc_peak >= min(br%p_star(i), br%p_star(i + 1)) .and. &
               cyc%p_fc_peak <= max(br%p_star(i), br%p_star(i + 1))
            exit
         end if
      end do
      call check(error, bracketed, "P_fc,peak inside the traced bracket")
   end subroutine test_fc_peak_gradual

   !> mu = 0.01 at alpha 10 and 3 (eps/Delta = 3420, 1600: the range far beyond the
   !> amplitude): the trace reaches full contact (its step scales with eps; at 0.1 Delta it
   !> needed ~1e5 points), and the pull-off is the flat surfaces' peak tension
   !> 16/(9 sqrt 3) sigma0 to 1e-3 (the wave is negligible against eps).
   subroutine test_long_range(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(lj_cycle_type) :: cyc
      real(wp) :: alphas(2)
      integer :: status, k
      character(len=256) :: msg
      alphas = [10.0_wp, 3.0_wp]
      do k = 1, 2
         msg = ""
         call new_params(alphas(k), 0.01_wp, params, status)
         call lj_cycle(params, cyc, status, msg)
         call check(error, status == wa_ok, "lj_cycle: "//trim(msg))
         if (allocated(error)) return
         call check_close(error, cyc%p_pf, -16.0_wp/(9.0_wp*sqrt(3.0_wp))*params%sigma0, &
            1.0e-3_wp, what="flat pull-off")
         if (allocated(error)) return
      end do
   end subroutine test_long_range

end module test_bem
