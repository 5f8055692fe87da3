!> The discretised equations of the smooth-adhesion model and their Newton solution
!> (doc/theory.md, "Smooth adhesion"). A point of the equilibrium curve is
!> z = (h_1..h_n, P*): the gaps at the unknown nodes and the mean load. Its equations are
!> the stationarity of the energy per period
!>   E = (1/2) mean(u K u) + mean(phi(h)) + P* gbar*,   u = h - f - delta,
!> with respect to every nodal gap, times N: r = W (K (h - f) + sigma(h) + P*) = 0
!> (W: node weights), whose Jacobian in h is the symmetric Hessian S = W (K + diag sigma').
!> A further linear equation a . z = target closes the system: a fixed mean gap, a fixed
!> load, or the pseudo-arclength hyperplane. The bordered system is solved by block
!> elimination on the Bunch-Kaufman factorisation of S, with one step of refinement
!> (stable at folds, where S is singular). Products with the stiffness go by FFT; above
!> dense_max_unknowns the preconditioner is the two-grid one of wa_bem_fast (no dense
!> factorisation of the fine grid) and the trace counts the inertia across its folds.
module wa_bem_solver
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_not_converged, wa_invalid_argument, wa_capacity_too_small, &
      set_error
   use wa_params, only: params_type, check_params
   use wa_bem_law, only: bem_law_type, lj_law, law_eval, law_zero, law_peak, law_potential
   use wa_bem_elastic, only: bem_grid_type, new_grid, stiffness_matrix, measure_below, &
      peak_value, kernel_value, full_period
   use wa_bem_dense, only: ldl_type, ldl_factor, ldl_solve
   use wa_bem_fast, only: fft_plans_type, plans_create, plans_destroy, circulant_symbol, &
      circulant_apply, twogrid_type, coarse_stiffness, twogrid_setup, twogrid_apply
   use, intrinsic :: iso_c_binding, only: c_associated
   implicit none
   private

   public :: lj_problem_type, jacobian_type, point_info_type
   public :: lj_problem, lj_auto_n, lj_zone_length, lj_max_unknowns, lj_max_auto_n
   public :: setup_operator, use_two_grid, jacobian_free, residual, factor_at, bordered_solve, newton, tangent_at, &
      point_info, metric_dot, gap_constraint, load_constraint, gap_energy

   !> The discretised problem: law, grid and the elastic stiffness W K.
   type :: lj_problem_type
      type(bem_law_type) :: law
      type(bem_grid_type) :: grid
      !> W K as a dense matrix (dense preconditioner only)
      real(wp), allocatable :: kw(:, :)
      !> The circulant's symbol over N in halfcomplex order (FFT products) and, for the two-grid
      !> preconditioner, the coarse circulant's column and the grid ratio
      real(wp), allocatable :: symbol(:), kc(:)
      logical :: two_grid = .false.
      integer :: ratio = 1
   end type lj_problem_type

   !> The Hessian S factorised at one point, with q = S^-1 w for the bordered solves.
   type :: jacobian_type
      type(ldl_type) :: fact
      !> the two-grid preconditioner (problem%two_grid) and the FFT plans (made at the
      !> first factor_at, freed by jacobian_free)
      type(twogrid_type) :: tg
      type(fft_plans_type) :: plans
      real(wp), allocatable :: dw(:), q(:)
      !> GMRES's Krylov basis, kept from call to call (krylov_solve)
      real(wp), allocatable :: basis(:, :)
      !> negative eigenvalues of the Hessians under load control (S) and gap control
      !> (S on mean-gap-preserving variations)
      integer :: neg_load = 0, neg_gap = 0
   end type jacobian_type

   !> What a point reports.
   type :: point_info_type
      real(wp) :: p = 0.0_wp, gbar = 0.0_wp, a_star = 0.0_wp, b_star = 0.0_wp, &
         h_min = 0.0_wp, h_max = 0.0_wp
   end type point_info_type

   !> A gap below this fraction of the law's zero is refused (a step that overshoots
   !> into the wall would find states of unphysical compression)
   real(wp), parameter :: h_floor_fraction = 0.1_wp
   !> GMRES iterations above which the preconditioner is refactorised
   integer, parameter :: krylov_refresh = 12
   !> GMRES iterations at most (no restart)
   integer, parameter :: krylov_dim = 40

   !> Cap of the unknowns per state (N/2 + 1 on an even profile, N otherwise): beyond
   !> dense_max_unknowns a state costs O(N) memory, and a branch of a few hundred states
   !> at the cap about 100 MB.
   integer, parameter :: lj_max_unknowns = 8193
   !> Cap of the unknowns of an uneven profile (whole period, dense factorisation: a few
   !> matrices of n^2 reals, about 100 MB at the cap)
   integer, parameter :: dense_uneven_max_unknowns = 2048
   !> Unknowns above which the preconditioner is the two-grid one (measured, at alpha 0.3,
   !> mu 3: the two-grid trace takes 0.5 s at N = 512 against 0.7 s with the dense one)
   integer, parameter :: dense_max_unknowns = 129
   !> Coarse period of the two-grid preconditioner: N/8, at least 128 (a coarser grid
   !> needs many more GMRES iterations: N = 4096 over 128 takes twice as long; N/16, or a
   !> cap of 1024 at N = 16384, triples the trace's points through refused steps: 71 s
   !> instead of 53 s at N = 16384, doc/accuracy-performance.md)
   integer, parameter :: coarse_min = 128, max_ratio = 8

   !> Time cap of the automatic grid: one cycle at N = 2048 takes 1.5 s at alpha 0.3, mu 3
   !> and 2.7 s at alpha 34.8, mu 21.9 (680 trace points: P* spans hundreds of units, in
   !> steps scaled by the law's peak tension) on one core (doc/accuracy-performance.md); a
   !> finer automatic grid is refused.
   integer, parameter :: lj_max_auto_n = 2048
   !> Largest range eps/Delta of the law: the trace starts with gaps of about 500 eps, whose
   !> rounding (500 eps 1.1e-16) must stay far below the profile's amplitude (1): at 1e5
   !> it is 6e-9. Beyond it the profile is lost in the gap's last bits (the fuzzer's
   !> alpha 5.5e7, mu 4.8e-5, eps = 6.9e14: a load of -1843 from rounding noise while the
   !> state's tractions mean -1.5e-7).
   real(wp), parameter :: lj_max_range = 1.0e5_wp
   !> Grid points the automatic N puts on the interaction zone
   real(wp), parameter :: points_per_zone = 12.0_wp

contains

   !> Length over L of the interaction zone, alpha^2/(2 Sigma0^2) (the cohesive zone of
   !> a crack in the JKR regime, doc/theory.md "Smooth adhesion").
   pure function lj_zone_length(params) result(ell)
      !> Validated dimensionless parameters alpha, mu (new_params), mu > 0 (at mu = 0,
      !> Sigma0 = 0 and the zone is unbounded)
      type(params_type), intent(in) :: params
      real(wp) :: ell
      ell = params%alpha**2/(2.0_wp*params%sigma0**2)
   end function lj_zone_length

   !> The automatic grid: the smallest power of two >= 128 that puts points_per_zone
   !> points on the interaction zone; 0 where that exceeds the cap n_max.
   pure function lj_auto_n(params, n_max) result(n)
      !> Validated dimensionless parameters alpha, mu (new_params), mu > 0 (lj_problem
      !> refuses mu = 0)
      type(params_type), intent(in) :: params
      !> The cap (absent: lj_max_auto_n = 2048)
      integer, intent(in), optional :: n_max
      integer :: n, cap
      real(wp) :: need
      cap = lj_max_auto_n
      if (present(n_max)) cap = n_max
      need = needed_n(params)
      n = 0
      if (need <= cap) n = nint(need)
   end function lj_auto_n

   !> The N the automatic rule needs, uncapped (a real: it may exceed any integer).
   pure function needed_n(params) result(n)
      type(params_type), intent(in) :: params
      real(wp) :: n, need
      need = points_per_zone/lj_zone_length(params)
      n = 128.0_wp
      do while (n < need .and. n < 1.0e300_wp)
         n = 2.0_wp*n
      end do
   end function needed_n

   !> The discretised problem of (alpha, mu) with the LJ law: n points per period (0 or
   !> absent: automatic), the profile as samples of one period over Delta (absent: the
   !> sinusoid 1 - cos 2 pi x). wa_invalid_argument for bad parameters (mu = 0 has no
   !> LJ law), wa_capacity_too_small where the grid exceeds the caps.
   subroutine lj_problem(params, problem, status, errmsg, n, profile, n_max)
      !> Dimensionless parameters alpha, mu (new_params; checked again here), mu > 0
      type(params_type), intent(in) :: params
      !> The discretised problem (law, grid of N points per period, stiffness), for lj_trace;
      !> incomplete on failure (not to be used)
      type(lj_problem_type), intent(out) :: problem
      !> wa_ok; wa_invalid_argument for bad params, mu = 0, a bad n or n_max or a profile of
      !> fewer than 4 samples; wa_capacity_too_small where the automatic grid would exceed
      !> its cap (n_max, default lj_max_auto_n = 2048; the message names the N needed) or
      !> the grid gives more than lj_max_unknowns = 8193 unknowns, or the law's range
      !> eps/Delta exceeds lj_max_range = 1e5
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or the cap)
      character(len=*), intent(inout), optional :: errmsg
      !> Grid points per period N: even and >= 8, at most 16384 on an even profile (N/2 + 1
      !> unknowns) and 8192 otherwise; 0 or absent: the automatic grid lj_auto_n(params)
      integer, intent(in), optional :: n
      !> The profile as samples of one period at x* = j/M, j = 0..M-1 (M >= 4), heights in
      !> units of Delta, resampled by its trigonometric interpolant (an uneven one with n <=
      !> 2048: it is solved densely on the whole period); an even profile
      !> (y(j) = y(M-j)) is solved on the half period; absent: the sinusoid 1 - cos 2 pi x*
      real(wp), intent(in), optional :: profile(:)
      !> Cap of the automatic grid, in [128, 16384]; 0 or absent: lj_max_auto_n = 2048
      !> (ignored with an explicit n)
      integer, intent(in), optional :: n_max
      integer :: np, cap
      character(len=24) :: text, needed, cap_text
      call check_params(params, status, errmsg)
      if (status /= wa_ok) return
      if (params%mu <= 0.0_wp) then
         call set_error(wa_invalid_argument, "mu = 0 has no Lennard-Jones law (its range "// &
            "would be infinite): mu must be > 0", status, errmsg)
         return
      end if
      problem%law = lj_law(params%alpha, params%mu)
      if (problem%law%eps > lj_max_range) then
         write (text, '(es10.3)') problem%law%eps
         call set_error(wa_capacity_too_small, "lj: the law's range eps/Delta = "// &
            trim(adjustl(text))//" = (4 alpha^4)^(1/3)/mu exceeds 1e5 (mu too small for "// &
            "alpha): the gaps, about 500 eps far apart, would not resolve the profile's "// &
            "amplitude in double precision", status, errmsg)
         return
      end if
      cap = lj_max_auto_n
      if (present(n_max)) then
         if (n_max /= 0 .and. (n_max < 128 .or. n_max > 2*(lj_max_unknowns - 1))) then
            call set_error(wa_invalid_argument, "n_max must be 0 (the default cap, 2048) "// &
               "or in [128, 16384]", status, errmsg)
            return
         end if
         if (n_max /= 0) cap = n_max
      end if
      np = 0
      if (present(n)) np = n
      if (np == 0) then
         np = lj_auto_n(params, cap)
         if (np == 0) then
            write (text, '(es10.3)') lj_zone_length(params)
            if (needed_n(params) < 2.0_wp**30) then
               write (needed, '(i0)') nint(needed_n(params))
            else
               write (needed, '(es10.3)') needed_n(params)
            end if
            write (cap_text, '(i0)') cap
            call set_error(wa_capacity_too_small, "lj: the interaction zone ("// &
               trim(adjustl(text))//" of a period) needs N = "//trim(adjustl(needed))// &
               " points per period, above the automatic grid's cap of "//trim(cap_text)// &
               "; pass n explicitly (at most 16384)", status, errmsg)
            return
         end if
      end if
      if (np <= 2*(lj_max_unknowns - 1)) call new_grid(np, problem%grid, status, errmsg, profile)
      if (status /= wa_ok) return
      ! (a larger n is refused before new_grid allocates its N points: n = 2^30 aborted)
      if (np > 2*(lj_max_unknowns - 1) .or. problem%grid%n > lj_max_unknowns) then
         call set_error(wa_capacity_too_small, "lj: n gives more than 8193 unknowns (n <= "// &
            "16384 on an even profile, n <= 8192 otherwise)", status, errmsg)
         return
      end if
      ! The two-grid preconditioner is validated on the half period of an even profile
      ! only; an uneven profile is solved with the dense factorisation, within its memory cap.
      if (.not. problem%grid%even .and. problem%grid%n > dense_uneven_max_unknowns) then
         call set_error(wa_capacity_too_small, "lj: an uneven profile is solved densely: "// &
            "n <= 2048 (the dense factorisation's memory cap)", status, errmsg)
         return
      end if
      call setup_operator(problem)
   end subroutine lj_problem

   !> The operators of problem%grid: the stiffness's symbol, and the dense W K (small
   !> grids) or the two-grid preconditioner's coarse operator.
   subroutine setup_operator(problem)
      type(lj_problem_type), intent(inout) :: problem
      integer :: np, nc
      np = problem%grid%n_period
      allocate (problem%symbol(0:np - 1))
      call circulant_symbol(kernel_value(np, [(nc, nc = 0, np - 1)]), problem%symbol)
      nc = max(coarse_min, np/max_ratio)
      if (problem%grid%n > dense_max_unknowns .and. mod(np, nc) == 0 .and. problem%grid%even) then
         call use_two_grid(problem, nc)
      else
         allocate (problem%kw(problem%grid%n, problem%grid%n))
         call stiffness_matrix(problem%grid, problem%kw)
      end if
   end subroutine setup_operator

   !> Switch problem to the two-grid preconditioner with coarse period nc (a divisor of
   !> N, at least 8, N/nc >= 2).
   subroutine use_two_grid(problem, nc)
      type(lj_problem_type), intent(inout) :: problem
      integer, intent(in) :: nc
      integer :: np, i
      np = problem%grid%n_period
      problem%two_grid = .true.
      problem%ratio = np/nc
      if (allocated(problem%kc)) deallocate (problem%kc)
      allocate (problem%kc(0:nc - 1))
      call coarse_stiffness(kernel_value(np, [(i, i = 0, np - 1)]), problem%symbol, &
         problem%ratio, problem%kc)
   end subroutine use_two_grid

   !> Free the FFT plans of jac (its owner calls this when done with it).
   subroutine jacobian_free(jac)
      type(jacobian_type), intent(inout) :: jac
      call plans_destroy(jac%plans)
   end subroutine jacobian_free

   !> y = W K x on the unknowns, by FFT (by the cosine transform of the half period on
   !> an even grid).
   subroutine stiffness_apply(problem, jac, x, y)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(in) :: jac
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: y(:)
      call circulant_apply(jac%plans, problem%symbol, x, y)
      y = problem%grid%w*y
   end subroutine stiffness_apply

   !> r = W (K (h - f) + sigma(h) + P) at z = (h, P); dw = W sigma'(h) where present.
   subroutine residual(problem, jac, z, r, dw)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(in) :: jac
      real(wp), intent(in) :: z(:)
      real(wp), intent(out) :: r(:)
      real(wp), intent(out), optional :: dw(:)
      real(wp) :: sig(problem%grid%n), slope(problem%grid%n)
      integer :: n
      n = problem%grid%n
      call law_eval(problem%law, z(1:n), sig, slope)
      call stiffness_apply(problem, jac, z(1:n) - problem%grid%f, r)
      r = r + problem%grid%w*(sig + z(n + 1))
      if (present(dw)) dw = problem%grid%w*slope
   end subroutine residual

   !> x ~ S^-1 b with the preconditioner in jac (exact on the dense path).
   subroutine solve_s(problem, jac, b, x)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(in) :: jac
      real(wp), intent(in) :: b(:)
      real(wp), intent(out) :: x(:)
      if (problem%two_grid) then
         ! S = W A: A^-1 (b/w), on the unknowns (an even field's half period)
         call twogrid_apply(jac%tg, jac%plans, problem%symbol, b/problem%grid%w, x)
      else
         x = b
         call ldl_solve(jac%fact, x)
      end if
   end subroutine solve_s

   !> Factorise S at z, with q = S^-1 w and the inertia under both controls (two-grid:
   !> the preconditioner at z, the inertia that of the coarse system, an estimate the
   !> trace uses only far apart).
   subroutine factor_at(problem, z, jac)
      type(lj_problem_type), intent(in) :: problem
      real(wp), intent(in) :: z(:)
      type(jacobian_type), intent(inout) :: jac
      real(wp), allocatable :: sig(:)
      integer :: n, i
      n = problem%grid%n
      allocate (sig(n))
      if (.not. allocated(jac%dw)) allocate (jac%dw(n), jac%q(n))
      call ensure_plans(problem, jac)
      call law_eval(problem%law, z(1:n), sig, jac%dw)
      if (problem%two_grid) then
         call twogrid_setup(full_period(problem%grid, jac%dw), problem%kc, problem%ratio, &
            problem%grid%even, jac%tg)
         jac%dw = problem%grid%w*jac%dw
         call solve_s(problem, jac, problem%grid%w, jac%q)
         jac%neg_load = jac%tg%coarse%negative + jac%tg%coarse%zero
         jac%neg_gap = jac%neg_load - 1
         if (dot_product(problem%grid%w, jac%q) > 0.0_wp) jac%neg_gap = jac%neg_gap + 1
         jac%neg_gap = max(jac%neg_gap, 0)
         return
      end if
      jac%dw = problem%grid%w*jac%dw
      if (.not. allocated(jac%fact%a)) allocate (jac%fact%a(n, n))
      jac%fact%a = problem%kw
      do i = 1, n
         jac%fact%a(i, i) = jac%fact%a(i, i) + jac%dw(i)
      end do
      call ldl_factor(jac%fact)
      jac%q = problem%grid%w
      call ldl_solve(jac%fact, jac%q)
      jac%neg_load = jac%fact%negative + jac%fact%zero
      ! inertia of [[S, w], [w^T, 0]] = inertia(S) + inertia(-w^T S^-1 w), which holds
      ! the gap-control Hessian's plus one positive and one negative eigenvalue
      jac%neg_gap = jac%neg_load - 1
      if (dot_product(problem%grid%w, jac%q) > 0.0_wp) jac%neg_gap = jac%neg_gap + 1
      jac%neg_gap = max(jac%neg_gap, 0)
   end subroutine factor_at

   !> The FFT plans of problem's grid in jac (made where missing or of another grid).
   subroutine ensure_plans(problem, jac)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: jac
      if (jac%plans%np /= problem%grid%n_period .or. (jac%plans%even .neqv. problem%grid%even)) &
         call plans_create(jac%plans, problem%grid%n_period, problem%grid%even)
   end subroutine ensure_plans

   !> The energy per period at fixed mean gap of state z (units p* Delta),
   !>   Pi = (1/2) mean(u K u) + mean phi(h),   u = h - f,
   !> E without its load term: along any curve of states dPi/dgbar* = -P*, so a jump at
   !> constant gbar* dissipates Pi(start) - Pi(end) (doc/theory.md, "Smooth adhesion").
   !> The stiffness product goes by FFT on u minus its mean (K annihilates constants, so
   !> the mean gap's rounding does not enter); jac only lends its FFT plans (made here
   !> where missing; the owner frees them with jacobian_free).
   function gap_energy(problem, jac, z) result(e)
      !> The problem the state belongs to
      type(lj_problem_type), intent(in) :: problem
      !> A workspace (its plans are made or reused)
      type(jacobian_type), intent(inout) :: jac
      !> A state (gaps at the unknown nodes, P*); only the gaps are read
      real(wp), intent(in) :: z(:)
      real(wp) :: e
      real(wp), allocatable :: u(:), ku(:)
      integer :: n
      n = problem%grid%n
      call ensure_plans(problem, jac)
      allocate (u(n), ku(n))
      u = z(1:n) - problem%grid%f
      u = u - sum(problem%grid%w*u)/problem%grid%n_period
      call stiffness_apply(problem, jac, u, ku)
      e = (0.5_wp*dot_product(u, ku) + sum(problem%grid%w*law_potential(problem%law, z(1:n)))) &
         /problem%grid%n_period
   end function gap_energy

   !> S_frozen x + w y = r1, a(1:n) . x + a(n+1) y = r2 (S as factorised in jac).
   subroutine bordered_solve(problem, jac, a, r1, r2, x, y)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: jac
      real(wp), intent(in) :: a(:), r1(:), r2
      real(wp), intent(out) :: x(:), y
      real(wp), allocatable :: e1(:), dx(:)
      real(wp) :: e2, dy
      integer :: n, pass
      logical :: ok
      n = problem%grid%n
      if (problem%two_grid) then            ! the preconditioner is not S^-1: iterate
         call krylov_solve(problem, jac, jac%dw, a, r1, r2, x, y, ok)
         if (ok) return
      end if
      allocate (e1(n), dx(n))
      e1 = r1
      e2 = r2
      x = 0.0_wp
      y = 0.0_wp
      do pass = 1, 2           ! block elimination, then one refinement with its residual
         call solve_s(problem, jac, e1, dx)
         dy = (e2 - dot_product(a(1:n), dx))/(a(n + 1) - dot_product(a(1:n), jac%q))
         dx = dx - jac%q*dy
         x = x + dx
         y = y + dy
         if (pass == 2) exit
         call stiffness_apply(problem, jac, x, e1)
         e1 = r1 - e1 - jac%dw*x - problem%grid%w*y
         e2 = r2 - dot_product(a(1:n), x) - a(n + 1)*y
      end do
   end subroutine bordered_solve

   !> a . z in the arclength metric (weights w/N on the gaps, 1 on the load).
   pure function metric_dot(problem, u, v) result(d)
      type(lj_problem_type), intent(in) :: problem
      real(wp), intent(in) :: u(:), v(:)
      real(wp) :: d
      integer :: n
      n = problem%grid%n
      d = sum(problem%grid%w*u(1:n)*v(1:n))/problem%grid%n_period + u(n + 1)*v(n + 1)
   end function metric_dot

   !> The row a of the constraint "mean gap fixed" (a . z = gbar*).
   pure function gap_constraint(problem) result(a)
      type(lj_problem_type), intent(in) :: problem
      real(wp) :: a(problem%grid%n + 1)
      a(1:problem%grid%n) = problem%grid%w/problem%grid%n_period
      a(problem%grid%n + 1) = 0.0_wp
   end function gap_constraint

   !> The row a of the constraint "load fixed" (a . z = P*).
   pure function load_constraint(problem) result(a)
      type(lj_problem_type), intent(in) :: problem
      real(wp) :: a(problem%grid%n + 1)
      a = 0.0_wp
      a(problem%grid%n + 1) = 1.0_wp
   end function load_constraint

   !> Newton on r(z) = 0, a . z = target from z: each step solves the exact Jacobian's
   !> bordered system by GMRES, preconditioned by the factorisation in jac (made at a
   !> nearby point); jac is refactorised at the iterate when GMRES needs too many
   !> iterations. status wa_not_converged where the iteration fails (the caller shortens
   !> its step).
   subroutine newton(problem, a, target, z, jac, status, n_factor, iterations)
      type(lj_problem_type), intent(in) :: problem
      real(wp), intent(in) :: a(:), target
      real(wp), intent(inout) :: z(:)
      type(jacobian_type), intent(inout) :: jac
      integer, intent(out) :: status
      integer, intent(inout) :: n_factor
      !> iterations taken
      integer, intent(out), optional :: iterations
      integer, parameter :: max_iter = 12
      real(wp), parameter :: tol = 1.0e-12_wp, tol_floor = 1.0e-10_wp
      real(wp), allocatable :: r(:), dx(:), dw(:)
      real(wp) :: dy, e, e_prev, eps, floor_h, eta
      integer :: n, it, refactor, its
      logical :: ok
      n = problem%grid%n
      allocate (r(n), dx(n), dw(n))
      eps = law_zero(problem%law)
      floor_h = h_floor_fraction*eps
      e_prev = huge(1.0_wp)
      refactor = 0
      status = wa_not_converged
      do it = 1, max_iter
         if (present(iterations)) iterations = it
         call residual(problem, jac, z, r, dw)
         ! inexact Newton: the linear residual need only shrink with the correction
         eta = max(1.0e-11_wp, min(1.0e-3_wp, e_prev**1.5_wp))
         call krylov_solve(problem, jac, dw, a, -r, target - dot_product(a, z), dx, dy, ok, &
            its, eta)
         if (ok .and. its > krylov_refresh .and. refactor < 2) then
            ! a stale preconditioner: refactorise here (one factorisation costs about as
            ! much as krylov_refresh iterations at n ~ 250, fewer beyond)
            call factor_at(problem, z, jac)
            n_factor = n_factor + 1
            refactor = refactor + 1
         end if
         if (.not. ok) then
            if (refactor >= 2) return
            call factor_at(problem, z, jac)
            n_factor = n_factor + 1
            refactor = refactor + 1
            call krylov_solve(problem, jac, dw, a, -r, target - dot_product(a, z), dx, dy, ok, &
               tolerance=eta)
            if (.not. ok) return
         end if
         z(1:n) = z(1:n) + dx
         z(n + 1) = z(n + 1) + dy
         if (any(.not. (z(1:n) > floor_h))) return        ! also catches NaN
         e = max(maxval(abs(dx)/max(abs(z(1:n)), eps)), abs(dy)/max(1.0_wp, abs(z(n + 1))))
         ! converged: the correction, or (converging fast) the next one e^2/e_prev, is
         ! below the tolerance
         if (e <= tol .or. (e <= 1.0e-8_wp .and. e*e <= tol*e_prev .and. e < 0.1_wp*e_prev)) then
            status = wa_ok
            return
         end if
         if (it > 1 .and. e > 0.3_wp*e_prev) then
            ! stagnation at the rounding floor of an ill-conditioned state (beside a fold):
            ! the corrections no longer shrink, and are far below what any output resolves
            if (e <= tol_floor) status = wa_ok
            if (e <= tol_floor .or. e > 2.0_wp*e_prev .or. it > 6) return
         end if
         e_prev = e
      end do
   end subroutine newton

   !> GMRES on [[S(z), w], [a]] [x, y] = [r1, r2] with S(z) = W K + diag(dw), right-
   !> preconditioned by the block elimination on the factorisation in jac. ok false when
   !> the relative residual (tolerance, default 1e-11) is not reached in krylov_dim
   !> iterations. The Krylov basis is jac's workspace (no allocation per solve).
   subroutine krylov_solve(problem, jac, dw, a, r1, r2, x, y, ok, iterations, tolerance)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: jac
      real(wp), intent(in) :: dw(:), a(:), r1(:), r2
      real(wp), intent(out) :: x(:), y
      logical, intent(out) :: ok
      !> GMRES iterations taken
      integer, intent(out), optional :: iterations
      !> relative residual asked for (default 1e-11)
      real(wp), intent(in), optional :: tolerance
      real(wp), allocatable :: v(:, :)
      integer :: its
      real(wp) :: rtol
      rtol = 1.0e-11_wp
      if (present(tolerance)) rtol = tolerance
      call move_alloc(jac%basis, v)        ! out of jac while jac is read below
      if (allocated(v)) then
         if (size(v, 1) /= size(r1) + 1) deallocate (v)
      end if
      if (.not. allocated(v)) allocate (v(size(r1) + 1, krylov_dim + 1))
      call gmres(problem, jac, dw, a, r1, r2, x, y, ok, its, rtol, v)
      call move_alloc(v, jac%basis)
      if (present(iterations)) iterations = its
   end subroutine krylov_solve

   !> krylov_solve's iteration, on the basis v (n + 1 by krylov_dim + 1).
   subroutine gmres(problem, jac, dw, a, r1, r2, x, y, ok, iterations, rtol, v)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(in) :: jac
      real(wp), intent(in) :: dw(:), a(:), r1(:), r2, rtol
      real(wp), intent(out) :: x(:), y, v(:, :)
      logical, intent(out) :: ok
      integer, intent(out) :: iterations
      integer, parameter :: m = krylov_dim
      real(wp) :: h(m + 1, m), g(m + 1), cs(m), sn(m), u(size(r1) + 1), pu(size(r1) + 1)
      real(wp) :: beta, tmp
      integer :: n, j, i, k
      n = problem%grid%n
      x = 0.0_wp
      y = 0.0_wp
      ok = .true.
      iterations = 0
      v(1:n, 1) = r1
      v(n + 1, 1) = r2
      beta = norm2(v(:, 1))
      if (beta == 0.0_wp) return
      v(:, 1) = v(:, 1)/beta
      g = 0.0_wp
      g(1) = beta
      ok = .false.
      do j = 1, m
         call precondition(problem, jac, a, v(:, j), pu)
         call apply_jacobian(problem, jac, dw, a, pu, u)
         do i = 1, j                                   ! modified Gram-Schmidt
            h(i, j) = dot_product(v(:, i), u)
            u = u - h(i, j)*v(:, i)
         end do
         h(j + 1, j) = norm2(u)
         if (h(j + 1, j) > 0.0_wp) v(:, j + 1) = u/h(j + 1, j)
         do i = 1, j - 1                               ! previous Givens rotations
            tmp = cs(i)*h(i, j) + sn(i)*h(i + 1, j)
            h(i + 1, j) = -sn(i)*h(i, j) + cs(i)*h(i + 1, j)
            h(i, j) = tmp
         end do
         tmp = hypot(h(j, j), h(j + 1, j))
         cs(j) = h(j, j)/tmp
         sn(j) = h(j + 1, j)/tmp
         h(j, j) = tmp
         h(j + 1, j) = 0.0_wp
         g(j + 1) = -sn(j)*g(j)
         g(j) = cs(j)*g(j)
         k = j
         iterations = j
         if (abs(g(j + 1)) <= rtol*beta .or. h(j, j) == 0.0_wp) then
            ok = abs(g(j + 1)) <= rtol*beta
            exit
         end if
      end do
      if (.not. ok) return
      do i = k, 1, -1                                  ! back substitution
         g(i) = (g(i) - dot_product(h(i, i + 1:k), g(i + 1:k)))/h(i, i)
      end do
      u = matmul(v(:, 1:k), g(1:k))
      call precondition(problem, jac, a, u, pu)
      x = pu(1:n)
      y = pu(n + 1)
   end subroutine gmres

   !> The bordered Jacobian at the current point times u.
   subroutine apply_jacobian(problem, jac, dw, a, u, ju)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(in) :: jac
      real(wp), intent(in) :: dw(:), a(:), u(:)
      real(wp), intent(out) :: ju(:)
      integer :: n
      n = problem%grid%n
      call stiffness_apply(problem, jac, u(1:n), ju(1:n))
      ju(1:n) = ju(1:n) + dw*u(1:n) + problem%grid%w*u(n + 1)
      ju(n + 1) = dot_product(a, u)
   end subroutine apply_jacobian

   !> Block elimination of the bordered system on the factorised (nearby) Hessian.
   subroutine precondition(problem, jac, a, u, pu)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(in) :: jac
      real(wp), intent(in) :: a(:), u(:)
      real(wp), intent(out) :: pu(:)
      integer :: n
      n = problem%grid%n
      call solve_s(problem, jac, u(1:n), pu(1:n))
      pu(n + 1) = (u(n + 1) - dot_product(a(1:n), pu(1:n)))/(a(n + 1) - dot_product(a(1:n), jac%q))
      pu(1:n) = pu(1:n) - jac%q*pu(n + 1)
   end subroutine precondition

   !> Unit tangent at z oriented along t_prev (the arclength row):
   !> [[S, w], [M t_prev]] t = [0, 1], normalised in the metric M; jac: the factorised
   !> Hessian at z or near it (the preconditioner), refactorised at z if GMRES fails.
   subroutine tangent_at(problem, jac, z, t_prev, t, n_factor)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: jac
      real(wp), intent(in) :: z(:), t_prev(:)
      real(wp), intent(out) :: t(:)
      integer, intent(inout) :: n_factor
      real(wp), allocatable :: a(:), zero(:), r(:), dw(:)
      real(wp) :: y
      integer :: n
      logical :: ok
      n = problem%grid%n
      allocate (a(n + 1), zero(n), r(n), dw(n))
      a(1:n) = problem%grid%w*t_prev(1:n)/problem%grid%n_period
      a(n + 1) = t_prev(n + 1)
      zero = 0.0_wp
      call residual(problem, jac, z, r, dw)
      call krylov_solve(problem, jac, dw, a, zero, 1.0_wp, t(1:n), y, ok)
      if (.not. ok) then
         call factor_at(problem, z, jac)
         n_factor = n_factor + 1
         call bordered_solve(problem, jac, a, zero, 1.0_wp, t(1:n), y)
      end if
      t(n + 1) = y
      t = t/sqrt(metric_dot(problem, t, t))
   end subroutine tangent_at

   !> Load, mean gap, a* (half the measure where h <= eps), b* (half the measure where
   !> h <= the gap of the peak tension), smallest and largest gap.
   pure function point_info(problem, z) result(info)
      type(lj_problem_type), intent(in) :: problem
      real(wp), intent(in) :: z(:)
      type(point_info_type) :: info
      integer :: n
      n = problem%grid%n
      info%p = z(n + 1)
      info%gbar = sum(problem%grid%w*z(1:n))/problem%grid%n_period
      info%a_star = 0.5_wp*measure_below(problem%grid, z(1:n), law_zero(problem%law))
      info%b_star = 0.5_wp*measure_below(problem%grid, z(1:n), law_peak(problem%law))
      info%h_min = peak_value(problem%grid, z(1:n), -1)
      info%h_max = peak_value(problem%grid, z(1:n), 1)
   end function point_info

end module wa_bem_solver
