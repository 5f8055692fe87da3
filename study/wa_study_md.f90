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
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_no_solution, wa_not_converged
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact
   use wa_md, only: md_psi_c
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_math, only: log1p
   use wa_psi_methods, only: psi_zone, k_gauss, k_qaws, k_adaptive
   implicit none
   private

   public :: md_variant, md_solve, psi_lib, psi_gauss, psi_qaws, psi_qag, psi_qags

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

   real(wp), parameter :: scan_step = 0.8_wp, x_limit = 300.0_wp
   integer, parameter :: max_iterations = 200


contains

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
      type(psi_zone) :: zz
      if (v%psi_method == psi_lib) then
         p = md_psi_c(geo%a_star, gap_of_x(geo, x))
         return
      end if
      zz = psi_zone(z%k**2, z%sn**2, z%omk2, z%cs**2)
      select case (v%psi_method)
      case (psi_gauss)
         p = k_gauss(zz, v%nodes)
      case (psi_qaws)
         p = k_qaws(zz, v%psi_tol)
      case default
         p = k_adaptive(zz, v%psi_method == psi_qags, v%psi_tol)
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

end module wa_study_md
