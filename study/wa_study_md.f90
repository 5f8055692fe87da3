!> A replica of the library's MD point solver (src/wa_md.f90: the residual
!> F(x) = opening - Dcod in x = ln tan s, the scan from the small-zone estimate in steps
!> of 0.8, Brent on the first sign change, the monotone stretch to c* = 1/2) with two
!> knobs: the way Psi_c (2.27d) is computed and Brent's absolute tolerance in x.
!> Hidden root pairs between scan samples are not searched for (the library does): the
!> study runs it only at points with a single case-1 root.
!>
!> Psi_c methods (the integral K of src/wa_md.f90's header; code of the GSL ones taken
!> from tools/md_quadrature_study.f90):
!>   lib      the library's fixed graded Gauss rules, through md_psi_c(a*, c*-a*)
!>   gauss-N  singularity subtraction only: an N-node Gauss rule for the weight -ln(1-r)
!>            plus N-node Gauss-Legendre for the ln(1+r) part
!>   qaws     GSL QAWS (weight ln(1-r)) + GSL QAG for the ln(1+r) part, epsrel tol
!>   qag      GSL QAG (GK21) of the whole log-singular integrand, epsrel tol
!>   qags     GSL QAGS (extrapolating) of the whole integrand, epsrel tol
module wa_study_md
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_size_t, &
      c_funloc, c_loc, c_f_pointer
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_no_solution, wa_not_converged
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact
   use wa_md, only: md_psi_c
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_math, only: log1p
   use wa_gsl, only: gsl_function, gsl_integration_workspace_alloc, &
      gsl_integration_workspace_free, gsl_integration_qaws_table_alloc, &
      gsl_integration_qaws_table_free, gsl_integration_qaws, gsl_integration_qag
   implicit none
   private

   public :: md_variant, md_solve, psi_lib, psi_gauss, psi_qaws, psi_qag, psi_qags
   public :: init_rules

   integer, parameter :: psi_lib = 1, psi_gauss = 2, psi_qaws = 3, psi_qag = 4, psi_qags = 5

   type :: md_variant
      integer :: psi_method = psi_lib
      !> epsrel of the GSL methods; nodes of gauss-N
      real(wp) :: psi_tol = 1.0e-10_wp
      integer :: nodes = 32
      !> Brent's absolute tolerance in x (the library: 4 eps)
      real(wp) :: xtol = 4.0_wp*epsilon(1.0_wp)
   end type md_variant

   type :: md_geometry
      real(wp) :: a_star = 0, a = 0, q = 0, opening_top = 0, x_mono = 0, x_top = 0
   end type md_geometry

   type :: md_zone
      real(wp) :: t = 0, r = 0, sn = 0, cs = 0, k = 0, omk2 = 0, chi2 = 0
   end type md_zone

   !> The integrand's parameters, passed to GSL through the context pointer.
   type :: zone_t
      real(wp) :: k2, s2, omk2, cs2
   end type zone_t

   real(wp), parameter :: scan_step = 0.8_wp, x_limit = 300.0_wp
   integer, parameter :: max_iterations = 200, max_nodes = 64
   !> Gauss-Legendre and Gauss-log rules on [0, 1], by number of nodes
   real(wp), save :: xg(max_nodes, max_nodes) = 0, wg(max_nodes, max_nodes) = 0
   real(wp), save :: xl(max_nodes, max_nodes) = 0, wl(max_nodes, max_nodes) = 0

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

contains

   !> Build the Gauss rules with 16, 32, 48, 64 nodes (once).
   subroutine init_rules()
      integer :: n
      do n = 16, max_nodes, 16
         call gauss_legendre01(n, xg(1:n, n), wg(1:n, n))
         call gauss_log01(n, xl(1:n, n), wl(1:n, n))
      end do
   end subroutine init_rules

   !> Principal MD state at a* (first case-1 root, else case 2), with the variant's
   !> Psi_c and tolerance; nres counts residual evaluations (each one Psi_c).
   subroutine md_solve(v, params, a_star, state, status, nres)
      type(md_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), intent(out) :: state
      integer, intent(out) :: status, nres
      type(md_geometry) :: geo
      real(wp) :: x_lo, f_lo, x_hi, f_hi, x
      integer :: i
      nres = 0
      status = wa_ok
      geo = geometry(a_star)
      if (a_star == 0.5_wp .or. params%sigma0 == 0.0_wp) then
         state = case2_state(params, geo)
         return
      end if
      ! no case-1 root at all: the opening stays below opening_top + Sigma0 artanh(q)
      if (params%dcod > geo%opening_top + params%sigma0*artanh_of(geo%q, geo%a**2)) then
         state = case2_state(params, geo)
         if (geo%opening_top > params%dcod) status = wa_no_solution
         return
      end if
      ! start below the first root (small-zone estimate), as the library
      x_lo = min(log(min(1.0_wp, sqrt(pi*params%dcod/(params%sigma0*geo%a*geo%q)), &
         (1.5_wp*params%dcod/(geo%a**2*geo%q**3))**(1.0_wp/3.0_wp))) - 1.5_wp, &
         geo%x_mono - scan_step)
      do i = 1, 40
         f_lo = residual(v, params, geo, x_lo, nres)
         if (f_lo < 0.0_wp) exit
         x_lo = x_lo - 3.0_wp
      end do
      if (f_lo >= 0.0_wp) then
         status = wa_not_converged
         return
      end if
      do
         x_hi = min(x_lo + scan_step, geo%x_mono)
         f_hi = residual(v, params, geo, x_hi, nres)
         if (f_hi >= 0.0_wp) exit
         x_lo = x_hi; f_lo = f_hi
         if (x_hi >= geo%x_mono) exit
      end do
      if (f_hi < 0.0_wp) then                 ! the monotone stretch up to c* = 1/2
         if (geo%opening_top - params%dcod < 0.0_wp) then
            if (geo%opening_top <= params%dcod) then
               state = case2_state(params, geo)
            else
               status = wa_no_solution
            end if
            return
         end if
         x_hi = geo%x_top
         f_hi = residual(v, params, geo, x_hi, nres)
         if (f_hi < 0.0_wp) then
            state = case1_state(params, geo, x_hi)
            return
         end if
      end if
      call refine(v, params, geo, x_lo, f_lo, x_hi, f_hi, x, status, nres)
      if (status == wa_ok) state = case1_state(params, geo, x)
   end subroutine md_solve

   subroutine refine(v, params, geo, x1, f1, x2, f2, x, status, nres)
      type(md_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x1, f1, x2, f2
      real(wp), intent(out) :: x
      integer, intent(out) :: status
      integer, intent(inout) :: nres
      type(brent_type) :: solver
      logical :: done
      integer :: iter
      call brent_init(solver, x1, f1, x2, f2, v%xtol)
      done = .false.
      do iter = 1, max_iterations
         call brent_propose(solver, x, done)
         if (done) exit
         call brent_accept(solver, residual(v, params, geo, x, nres))
      end do
      x = solver%b
      status = merge(wa_ok, wa_not_converged, done)
   end subroutine refine

   !> opening - Dcod, (2.27b)
   function residual(v, params, geo, x, nres) result(f)
      type(md_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      integer, intent(inout) :: nres
      real(wp) :: f
      type(md_zone) :: z
      nres = nres + 1
      if (x >= x_limit) then
         f = geo%opening_top - params%dcod
         return
      end if
      z = zone_at(geo, x)
      f = geo%a**2*excess(z%k, z%omk2, z%chi2) &
         + params%sigma0*((2.0_wp/pi)*atan(geo%a*z%t)*z%chi2 + psi(v, geo, z, x)) - params%dcod
   end function residual

   !> Psi_c by the variant's method.
   function psi(v, geo, z, x) result(p)
      type(md_variant), intent(in) :: v
      type(md_geometry), intent(in) :: geo
      type(md_zone), intent(in) :: z
      real(wp), intent(in) :: x
      real(wp) :: p
      type(zone_t) :: zz
      if (v%psi_method == psi_lib) then
         p = md_psi_c(geo%a_star, gap_of_x(geo, x))
         return
      end if
      zz = zone_t(z%k**2, z%sn**2, z%omk2, z%cs**2)
      select case (v%psi_method)
      case (psi_gauss)
         p = k_gauss(zz, v%nodes)
      case (psi_qaws)
         p = k_qaws(zz, v%psi_tol)
      case default
         p = k_adaptive(zz, v%psi_method, v%psi_tol)
      end select
      p = -(2.0_wp/pi)*geo%a*geo%q*z%sn**2*p
   end function psi

   ! ------------------------------------------------ geometry (copies of src/wa_md.f90)

   pure function geometry(a_star) result(geo)
      real(wp), intent(in) :: a_star
      type(md_geometry) :: geo
      real(wp) :: tan_a
      geo%a_star = a_star
      geo%a = sin(pi*a_star)
      geo%q = sin(pi*(0.5_wp - a_star))
      geo%opening_top = geo%a**2*excess(geo%q, geo%a**2, artanh_of(geo%q, geo%a**2))
      tan_a = geo%a/geo%q
      geo%x_mono = log(max(50.0_wp, 32.0_wp/tan_a))
      geo%x_top = min(x_limit, max(geo%x_mono + 1.0_wp, log(2.0_wp**56/(pi*tan_a))))
   end function geometry

   pure function zone_at(geo, x) result(z)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      type(md_zone) :: z
      z%t = exp(min(x, x_limit))
      z%r = sqrt(1.0_wp + z%t**2)
      z%sn = z%t/z%r
      z%cs = 1.0_wp/z%r
      z%k = geo%q*z%sn
      z%omk2 = z%cs**2 + (geo%a*z%sn)**2
      z%chi2 = artanh_of(z%k, z%omk2)
   end function zone_at

   pure function excess(k, omk2, chi2) result(e)
      real(wp), intent(in) :: k, omk2, chi2
      real(wp) :: e, k2, series
      integer :: j
      if (k >= 0.25_wp) then
         e = k/omk2 - chi2
         return
      end if
      k2 = k*k
      series = 1.0_wp/29.0_wp
      do j = 12, 0, -1
         series = 1.0_wp/real(2*j + 3, wp) + k2*series
      end do
      e = k*k2*(1.0_wp/omk2 - series)
   end function excess

   pure function artanh_of(k, omk2) result(y)
      real(wp), intent(in) :: k, omk2
      real(wp) :: y
      y = 0.5_wp*log1p(2.0_wp*k*(1.0_wp + k)/omk2)
   end function artanh_of

   pure function gap_of_x(geo, x) result(gap)
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      real(wp) :: gap
      type(md_zone) :: z
      z = zone_at(geo, x)
      gap = atan2(geo%a*geo%q*z%t*(z%t/(z%r + 1.0_wp)), geo%q**2 + geo%a**2*z%r)/pi
      gap = min(gap, 0.5_wp - geo%a_star)
   end function gap_of_x

   pure function case1_state(params, geo, x) result(state)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      real(wp), intent(in) :: x
      type(state_type) :: state
      state%a_star = geo%a_star
      state%gap_width = gap_of_x(geo, x)
      state%c_star = min(0.5_wp, geo%a_star + state%gap_width)
      state%p_star = geo%a**2 - params%sigma0*(2.0_wp/pi)*atan(geo%a*exp(min(x, x_limit)))
      state%zone_case = zone_inside
   end function case1_state

   pure function case2_state(params, geo) result(state)
      type(params_type), intent(in) :: params
      type(md_geometry), intent(in) :: geo
      type(state_type) :: state
      state%a_star = geo%a_star
      state%c_star = 0.5_wp
      state%gap_width = 0.5_wp - geo%a_star
      state%p_star = geo%a**2 - params%sigma0
      state%zone_case = zone_whole_period
      if (geo%a_star == 0.5_wp) state%zone_case = zone_full_contact
   end function case2_state

   ! ------------------------------ Psi_c alternatives (from tools/md_quadrature_study.f90)

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
         total = total + 0.5_wp*wl(i, nodes)*rg(z, 1.0_wp - xl(i, nodes)) &
            + 0.5_wp*wg(i, nodes)*log(1.0_wp + xg(i, nodes))*rg(z, xg(i, nodes))
      end do
   end function k_gauss

   function k_qaws(z, tol) result(total)
      type(zone_t), intent(in), target :: z
      real(wp), intent(in) :: tol
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
      call gsl_integration_qaws_table_free(table)
      call gsl_integration_workspace_free(work)
      total = -0.5_wp*r1 + 0.5_wp*r2
   end function k_qaws

   function k_adaptive(z, method, tol) result(total)
      type(zone_t), intent(in), target :: z
      integer, intent(in) :: method
      real(wp), intent(in) :: tol
      real(wp) :: total
      type(gsl_function) :: f
      type(c_ptr) :: work
      real(c_double) :: err
      integer(c_int) :: st
      integer(c_size_t), parameter :: limit = 1000
      work = gsl_integration_workspace_alloc(limit)
      f%params = c_loc(z)
      f%function = c_funloc(f_full)
      if (method == psi_qag) then
         st = gsl_integration_qag(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            2_c_int, work, total, err)
      else
         st = gsl_integration_qags(f, 0.0_c_double, 1.0_c_double, 0.0_c_double, tol, limit, &
            work, total, err)
      end if
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

   !> Gauss rule for the weight -ln(u) on [0, 1]: modified Chebyshev algorithm on shifted
   !> Legendre moments, then the Jacobi matrix's eigensystem (implicit QL).
   subroutine gauss_log01(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: alpha(n), beta(n)
      real(wp) :: mom(0:2*n - 1), a(0:2*n - 1), b(0:2*n - 1), sig(-1:2*n, 0:2*n), c
      integer :: k, l
      do k = 0, 2*n - 1
         a(k) = 0.5_wp
         b(k) = merge(1.0_wp, real(k, wp)**2/(4*(4*real(k, wp)**2 - 1)), k == 0)
      end do
      mom(0) = 1
      c = 1
      do k = 1, 2*n - 1
         c = c*real(k, wp)/real(2*(2*k - 1), wp)
         mom(k) = (-1)**k*c/real(k*(k + 1), wp)
      end do
      sig = 0
      sig(0, 0:2*n - 1) = mom(0:2*n - 1)
      alpha(1) = a(0) + mom(1)/mom(0)
      beta(1) = mom(0)
      do k = 1, n - 1
         do l = k, 2*n - k - 1
            sig(k, l) = sig(k - 1, l + 1) - (alpha(k) - a(l))*sig(k - 1, l) &
               - beta(k)*merge(0.0_wp, sig(max(k - 2, -1), l), k < 2) + b(l)*sig(k - 1, l - 1)
         end do
         alpha(k + 1) = a(k) + sig(k, k + 1)/sig(k, k) - sig(k - 1, k)/sig(k - 1, k - 1)
         beta(k + 1) = sig(k, k)/sig(k - 1, k - 1)
      end do
      call golub_welsch(n, alpha, beta, x, w)
   end subroutine gauss_log01

   subroutine golub_welsch(n, alpha, beta, x, w)
      integer, intent(in) :: n
      real(wp), intent(in) :: alpha(n), beta(n)
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: d(n), e(n), zz(n), gg, r, s, c, p, f, b, vx, vw
      integer :: l, m, i, iter, j
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
      do i = 2, n                                   ! sort by node
         vx = x(i); vw = w(i); j = i - 1
         do while (j >= 1)
            if (x(j) <= vx) exit
            x(j + 1) = x(j); w(j + 1) = w(j); j = j - 1
         end do
         x(j + 1) = vx; w(j + 1) = vw
      end do
   end subroutine golub_welsch

end module wa_study_md
