!> Error against run time of the ways to compute Psi_c (2.27d) for the MD model.
!>
!> Reference: tools/md_psi_reference.txt (mpmath, 32 digits, tools/md_reference.py), 64
!> cases a* in {1e-12, 1e-6, 1e-3, 0.05, 0.25, 0.45, 1/2-1e-6, 1/2-1e-12} times
!> gap/(1/2-a*) in {1e-12, 1e-6, 0.01, 0.3, 0.7, 0.99, 1-1e-6, 1-1e-10}; "core" is the
!> subset a* in [1e-3, 0.45], gap/(1/2-a*) in [0.01, 0.99], "mid" the same with
!> gap/(1/2-a*) <= 0.7. Times are medians over the 64 cases and over the core cases
!> (best of 3 runs each).
!> gsl_fail counts the cases where GSL returned a non-zero status (its value is then
!> whatever it returned). GSL refuses epsrel < 50 eps = 1.1e-14 (epsabs = 0).
!> All methods integrate K = int_0^1 artanh(r) r G(r) dr,
!> G = 1/((1 - k^2 r^2) sqrt(1 - sin^2 s r^2)), Psi_c = -(2/pi) A q sin^2 s K:
!>   lib      the library's fixed graded Gauss rules (md_psi_c, src/wa_md.f90; the time
!>            includes forming T, sin s, k from (a*, gap), about 0.1 us)
!>   gauss-N  one Gauss rule for the weight -ln(1-r) (N nodes) for -(1/2)ln(1-r) r G, plus
!>            N-point Gauss-Legendre for (1/2) ln(1+r) r G: singularity subtraction only
!>   qaws     GSL QAWS (weight ln(1-r)) + GSL QAG (GK21) for the ln(1+r) part, epsrel tol
!>   qag      GSL QAG (GK21) on the whole integrand, epsrel tol
!>   qags     GSL QAGS (extrapolating) on the whole integrand, epsrel tol
!> GSL workspaces and tables are allocated and freed per call, as a library would.
!> Build and run from the repository root with tools/md_study.sh study.
program md_quadrature_study
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_size_t, c_funptr, &
      c_funloc, c_loc, c_f_pointer, c_associated
   use, intrinsic :: iso_fortran_env, only: int64
   use wa_kinds, only: wp, pi
   use wa_md, only: md_psi_c
   use wa_gsl, only: gsl_function, gsl_set_error_handler_off, &
      gsl_integration_workspace_alloc, gsl_integration_workspace_free, &
      gsl_integration_qaws_table_alloc, gsl_integration_qaws_table_free, &
      gsl_integration_qaws, gsl_integration_qag
   implicit none

   interface
      function gsl_integration_qags(f, a, b, epsabs, epsrel, limit, workspace, &
            result, abserr) result(status) bind(C, name="gsl_integration_qags")
         import :: gsl_function, c_double, c_size_t, c_ptr, c_int
         type(gsl_function), intent(in) :: f
         real(c_double), value :: a, b, epsabs, epsrel
         integer(c_size_t), value :: limit
         type(c_ptr), value :: workspace
         real(c_double), intent(out) :: result, abserr
         integer(c_int) :: status
      end function gsl_integration_qags
   end interface

   !> The integrand's parameters, passed to GSL through the context pointer.
   type :: zone_t
      real(wp) :: k2, s2, omk2, cs2
   end type zone_t

   integer, parameter :: max_cases = 200, max_nodes = 64
   real(wp) :: a(max_cases), g(max_cases), ref(max_cases)
   !> Gauss-Legendre and Gauss-log rules on [0, 1], built once (index: number of nodes)
   real(wp) :: xg(max_nodes, max_nodes), wg(max_nodes, max_nodes)
   real(wp) :: xl(max_nodes, max_nodes), wl(max_nodes, max_nodes)
   integer :: n, u, ios, n_rule
   character(len=200) :: line
   type(c_funptr) :: old

   old = gsl_set_error_handler_off()
   open (newunit=u, file="tools/md_psi_reference.txt", status="old", action="read")
   n = 0
   do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == "#") cycle
      n = n + 1
      read (line, *) a(n), g(n), ref(n)
   end do
   close (u)

   do n_rule = 16, max_nodes, 16
      call gauss_legendre01(n_rule, xg(1:n_rule, n_rule), wg(1:n_rule, n_rule))
      call gauss_log01(n_rule, xl(1:n_rule, n_rule), wl(1:n_rule, n_rule))
   end do
   print '(a)', "# method        tol      max_err_all  max_err_core   max_err_mid  " &
      //"median_us  (core)  gsl_fail"
   call run("lib", 0, 0.0_wp)
   call run("gauss", 16, 0.0_wp)
   call run("gauss", 32, 0.0_wp)
   call run("gauss", 64, 0.0_wp)
   call run("qaws", 0, 1e-10_wp)
   call run("qaws", 0, 1e-12_wp)
   call run("qaws", 0, 1.2e-14_wp)
   call run("qag", 0, 1e-10_wp)
   call run("qag", 0, 1.2e-14_wp)
   call run("qags", 0, 1e-10_wp)
   call run("qags", 0, 1.2e-14_wp)

contains

   !> Max relative error (all cases, core cases) and median time per Psi_c of one method.
   subroutine run(method, nodes, tol)
      character(len=*), intent(in) :: method
      integer, intent(in) :: nodes
      real(wp), intent(in) :: tol
      real(wp) :: t(n), t_core(n), err_all, err_core, err_mid, v, e, frac
      integer :: i, r, reps, fails, st, dummy, n_core
      integer(int64) :: c0, c1, rate
      character(len=16) :: label

      call system_clock(count_rate=rate)
      err_all = 0; err_core = 0; err_mid = 0; fails = 0; n_core = 0
      reps = merge(2000, 20, method == "lib" .or. method == "gauss")
      do i = 1, n
         t(i) = huge(1.0_wp)
         do r = 1, 3
            call system_clock(c0)
            do st = 1, reps
               v = psi(method, nodes, tol, a(i), g(i), dummy)
            end do
            call system_clock(c1)
            t(i) = min(t(i), real(c1 - c0, wp)/real(rate, wp)/reps*1e6_wp)
         end do
         v = psi(method, nodes, tol, a(i), g(i), fails)
         e = abs(v - ref(i))/abs(ref(i))
         if (.not. (e == e)) e = huge(1.0_wp)
         err_all = max(err_all, e)
         frac = g(i)/(0.5_wp - a(i))
         if (a(i) >= 1e-3_wp .and. a(i) <= 0.45_wp .and. frac >= 0.01_wp .and. frac <= 0.99_wp) then
            err_core = max(err_core, e)
            n_core = n_core + 1
            t_core(n_core) = t(i)
         end if
         if (a(i) >= 1e-3_wp .and. a(i) <= 0.45_wp .and. frac >= 0.01_wp .and. frac <= 0.7_wp) &
            err_mid = max(err_mid, e)
      end do
      call sort(t)
      call sort(t_core(1:n_core))
      label = method
      if (nodes > 0) write (label, '(a,"-",i0)') method, nodes
      print '(a14, es9.1, 3es14.2, 2f11.3, i9)', label, tol, err_all, err_core, err_mid, &
         t((n + 1)/2), t_core((n_core + 1)/2), fails
   end subroutine run

   function psi(method, nodes, tol, a_star, gap, fails) result(v)
      character(len=*), intent(in) :: method
      integer, intent(in) :: nodes
      real(wp), intent(in) :: tol, a_star, gap
      integer, intent(inout) :: fails
      real(wp) :: v
      type(zone_t), target :: z
      real(wp) :: aa, q, rm1, r, tt, sn, cs, kk

      if (method == "lib") then
         v = md_psi_c(a_star, gap)
         return
      end if
      aa = sin(pi*a_star)
      q = sin(pi*(0.5_wp - a_star))
      rm1 = sin(pi*gap)/(aa*sin(pi*((0.5_wp - a_star) - gap)))
      r = rm1 + 1.0_wp
      tt = sqrt(rm1*(rm1 + 2.0_wp))
      sn = tt/r
      cs = 1.0_wp/r
      kk = q*sn
      z = zone_t(kk**2, sn**2, cs**2 + (aa*sn)**2, cs**2)
      select case (method)
      case ("gauss")
         v = k_gauss(z, nodes)
      case ("qaws")
         v = k_qaws(z, tol, fails)
      case default
         v = k_adaptive(z, method, tol, fails)
      end select
      v = -(2.0_wp/pi)*aa*q*sn**2*v
   end function psi

   !> r G(r) with 1 - k^2 r^2 and 1 - sin^2 r^2 formed from 1 - r without cancellation.
   pure function rg(z, r) result(f)
      type(zone_t), intent(in) :: z
      real(wp), intent(in) :: r
      real(wp) :: f, y2
      y2 = (1.0_wp - r)*(1.0_wp + r)
      f = r/((z%omk2 + z%k2*y2)*sqrt(z%cs2 + z%s2*y2))
   end function rg

   function k_gauss(z, nodes) result(total)
      type(zone_t), intent(in) :: z
      integer, intent(in) :: nodes
      real(wp) :: total
      integer :: i
      total = 0
      do i = 1, nodes
         ! weight -ln(u), u = 1 - r:  -(1/2) ln(1-r) r G
         total = total + 0.5_wp*wl(i, nodes)*rg(z, 1.0_wp - xl(i, nodes)) &
            + 0.5_wp*wg(i, nodes)*log(1.0_wp + xg(i, nodes))*rg(z, xg(i, nodes))
      end do
   end function k_gauss

   function k_qaws(z, tol, fails) result(total)
      type(zone_t), intent(in), target :: z
      real(wp), intent(in) :: tol
      integer, intent(inout) :: fails
      real(wp) :: total
      type(gsl_function) :: f
      type(c_ptr) :: work, table
      real(c_double) :: r1, r2, err
      integer(c_int) :: st1, st2
      integer(c_size_t), parameter :: limit = 1000

      work = gsl_integration_workspace_alloc(limit)
      table = gsl_integration_qaws_table_alloc(0.0_c_double, 0.0_c_double, 0_c_int, 1_c_int)
      f%params = c_loc(z)
      f%function = c_funloc(f_rg)
      st1 = gsl_integration_qaws(f, 0.0_c_double, 1.0_c_double, table, 0.0_c_double, tol, &
         limit, work, r1, err)
      f%function = c_funloc(f_log1p_rg)
      st2 = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
         2_c_int, work, r2, err)
      if (st1 /= 0 .or. st2 /= 0) fails = fails + 1
      call gsl_integration_qaws_table_free(table)
      call gsl_integration_workspace_free(work)
      total = -0.5_wp*r1 + 0.5_wp*r2
   end function k_qaws

   function k_adaptive(z, method, tol, fails) result(total)
      type(zone_t), intent(in), target :: z
      character(len=*), intent(in) :: method
      real(wp), intent(in) :: tol
      integer, intent(inout) :: fails
      real(wp) :: total
      type(gsl_function) :: f
      type(c_ptr) :: work
      real(c_double) :: err
      integer(c_int) :: st
      integer(c_size_t), parameter :: limit = 1000

      work = gsl_integration_workspace_alloc(limit)
      f%params = c_loc(z)
      f%function = c_funloc(f_full)
      if (method == "qag") then
         st = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            2_c_int, work, total, err)
      else
         st = gsl_integration_qags(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            work, total, err)
      end if
      if (st /= 0) fails = fails + 1
      call gsl_integration_workspace_free(work)
   end function k_adaptive

   function f_rg(r, ctx) result(f) bind(C)
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(zone_t), pointer :: z
      call c_f_pointer(ctx, z)
      f = rg(z, r)
   end function f_rg

   function f_log1p_rg(r, ctx) result(f) bind(C)
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(zone_t), pointer :: z
      call c_f_pointer(ctx, z)
      f = log(1.0_wp + r)*rg(z, r)
   end function f_log1p_rg

   function f_full(r, ctx) result(f) bind(C)
      real(c_double), value :: r
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(zone_t), pointer :: z
      call c_f_pointer(ctx, z)
      f = 0.0_wp
      if (r < 1.0_wp) f = 0.5_wp*log((1.0_wp + r)/(1.0_wp - r))*rg(z, r)
   end function f_full

   !> Gauss-Legendre on [0, 1] (Newton on P_n).
   subroutine gauss_legendre01(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: z, p0, p1, p2, dp
      integer :: i, j, it
      do i = 1, n
         z = cos(pi*(i - 0.25_wp)/(n + 0.5_wp))
         do it = 1, 100
            p0 = 1; p1 = z
            do j = 2, n
               p2 = ((2*j - 1)*z*p1 - (j - 1)*p0)/j
               p0 = p1; p1 = p2
            end do
            dp = n*(z*p1 - p0)/(z*z - 1)
            z = z - p1/dp
            if (abs(p1/dp) < 1e-16_wp) exit
         end do
         x(i) = 0.5_wp*(1 - z)
         w(i) = 1/((1 - z*z)*dp*dp)
      end do
   end subroutine gauss_legendre01

   !> Gauss rule for the weight -ln(u) on [0, 1] from its modified moments against
   !> shifted Legendre polynomials (modified Chebyshev algorithm, Gautschi), then
   !> eigenvalues of the Jacobi matrix by the implicit QL algorithm.
   subroutine gauss_log01(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: alpha(n), beta(n)
      call log_recurrence(n, alpha, beta)
      call golub_welsch(n, alpha, beta, x, w)
   end subroutine gauss_log01

   !> Recurrence coefficients of the orthogonal polynomials for -ln(u) on [0, 1]
   !> (modified Chebyshev algorithm with shifted monic Legendre polynomials).
   subroutine log_recurrence(n, alpha, beta)
      integer, intent(in) :: n
      real(wp), intent(out) :: alpha(n), beta(n)
      real(wp) :: mom(0:2*n - 1), a(0:2*n - 1), b(0:2*n - 1)
      real(wp) :: sig(-1:2*n, 0:2*n)
      integer :: k, l
      real(wp) :: c
      ! monic shifted Legendre on [0,1]: a_k = 1/2, b_k = k^2/(4(4k^2-1))
      do k = 0, 2*n - 1
         a(k) = 0.5_wp
         b(k) = merge(1.0_wp, real(k, wp)**2/(4*(4*real(k, wp)**2 - 1)), k == 0)
      end do
      ! modified moments of -ln u against monic shifted Legendre pi_k:
      ! int -ln(u) P*_k(u) du = (-1)^k/(k(k+1)), P*_k = ((2k)!/(k!)^2) pi_k, so
      ! m_k = (-1)^k (k!)^2/((2k)! k (k+1)) for k >= 1, m_0 = 1
      mom(0) = 1
      c = 1
      do k = 1, 2*n - 1
         c = c*real(k, wp)/real(2*(2*k - 1), wp)     ! (k!)^2/(2k)! recursively
         mom(k) = (-1)**k*c/real(k*(k + 1), wp)
      end do
      sig = 0
      sig(0, 0:2*n - 1) = mom(0:2*n - 1)
      alpha(1) = a(0) + mom(1)/mom(0)
      beta(1) = mom(0)
      do k = 1, n - 1
         do l = k, 2*n - k - 1
            sig(k, l) = sig(k - 1, l + 1) - (alpha(k) - a(l))*sig(k - 1, l) &
               - beta(k)*merge(0.0_wp, sig(k - 2, l), k < 2) + b(l)*sig(k - 1, l - 1)
         end do
         alpha(k + 1) = a(k) + sig(k, k + 1)/sig(k, k) - sig(k - 1, k)/sig(k - 1, k - 1)
         beta(k + 1) = sig(k, k)/sig(k - 1, k - 1)
      end do
   end subroutine log_recurrence

   !> Nodes and weights from the Jacobi matrix (symmetric tridiagonal QL, tqli-style).
   subroutine golub_welsch(n, alpha, beta, x, w)
      integer, intent(in) :: n
      real(wp), intent(in) :: alpha(n), beta(n)
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: d(n), e(n), zz(n), gg, r, s, c, p, f, b
      integer :: l, m, i, iter
      d = alpha
      e(1:n - 1) = sqrt(beta(2:n)); e(n) = 0
      zz = 0; zz(1) = 1
      do l = 1, n
         iter = 0
         do
            do m = l, n - 1
               if (abs(e(m)) <= epsilon(1.0_wp)*(abs(d(m)) + abs(d(m + 1)))) exit
            end do
            if (m == l) exit
            iter = iter + 1
            gg = (d(l + 1) - d(l))/(2*e(l)); r = hypot(gg, 1.0_wp)
            gg = d(m) - d(l) + e(l)/(gg + sign(r, gg))
            s = 1; c = 1; p = 0
            do i = m - 1, l, -1
               f = s*e(i); b = c*e(i)
               r = hypot(f, gg); e(i + 1) = r
               if (r == 0) then
                  d(i + 1) = d(i + 1) - p; e(m) = 0; exit
               end if
               s = f/r; c = gg/r; gg = d(i + 1) - p
               r = (d(i) - gg)*s + 2*c*b; p = s*r; d(i + 1) = gg + p; gg = c*r - b
               f = zz(i + 1); zz(i + 1) = s*zz(i) + c*f; zz(i) = c*zz(i) - s*f
            end do
            if (r == 0 .and. i >= l) cycle
            d(l) = d(l) - p; e(l) = gg; e(m) = 0
         end do
      end do
      x = d; w = beta(1)*zz**2
      call sort2(x, w)
   end subroutine golub_welsch

   subroutine sort2(x, w)
      real(wp), intent(inout) :: x(:), w(:)
      integer :: i, j
      real(wp) :: vx, vw
      do i = 2, size(x)
         vx = x(i); vw = w(i); j = i - 1
         do while (j >= 1)
            if (x(j) <= vx) exit
            x(j + 1) = x(j); w(j + 1) = w(j); j = j - 1
         end do
         x(j + 1) = vx; w(j + 1) = vw
      end do
   end subroutine sort2

   subroutine sort(t)
      real(wp), intent(inout) :: t(:)
      real(wp) :: x(size(t))
      x = t
      call sort2(t, x)
   end subroutine sort

end program md_quadrature_study
