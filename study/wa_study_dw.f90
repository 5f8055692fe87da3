!> A replica of the library's DW point solver (src/wa_dw.f90: dw_equilibrium, the
!> residual G(u) of doc/theory.md, the bracket around the large-mu estimate, Brent in
!> u = ln s) with two knobs the library fixes: how W = I*/(C^2-A^2)^2 is computed and
!> Brent's absolute tolerance in u. With w_agm and xtol = 4 eps it reproduces
!> dw_equilibrium bit for bit (checked at run time by the study) and also counts
!> residual evaluations, which the library does not expose.
module wa_study_dw
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_size_t, &
      c_funloc, c_loc, c_f_pointer
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_no_solution, wa_not_converged
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact
   use wa_elliptic, only: istar_scaled, istar_carlson, istar_quadrature, ia_star
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_math, only: log1p, sincos_pi
   use wa_gsl, only: gsl_function, gsl_integration_workspace_alloc, &
      gsl_integration_workspace_free, gsl_integration_qag
   implicit none
   private

   public :: dw_variant, dw_solve, w_agm, w_carlson, w_tanh_sinh, w_qag

   !> Ways to compute W: the library's closed form (Bartky's AGM, default), the Carlson
   !> form with GSL's R_F, R_D, R_J, the library's tanh-sinh quadrature of (E1) (which
   !> takes A and C and forms C^2-A^2 = (C-A)(C+A) itself), GSL QAG (Gauss-Kronrod 21)
   !> of (E1) on the accurate coefficients.
   integer, parameter :: w_agm = 1, w_carlson = 2, w_tanh_sinh = 3, w_qag = 4

   !> One numerical configuration.
   type :: dw_variant
      integer :: w_method = w_agm
      !> quadrature tolerance (tanh-sinh, QAG)
      real(wp) :: w_tol = 1.0e-15_wp
      !> Brent's absolute tolerance in u = ln s (the library: 4 eps)
      real(wp) :: xtol = 4.0_wp*epsilon(1.0_wp)
   end type dw_variant

   type :: contact_geometry
      real(wp) :: a_star, a, one_minus_a, one_minus_a2, cos_a
   end type contact_geometry

   !> (E1) coefficients for the GSL callback.
   type :: e1_coef
      real(wp) :: a1, b1, a2, b2
   end type e1_coef

   integer, parameter :: max_iterations = 100

contains

   !> Principal DW state at a*, as dw_equilibrium, with the variant's W and tolerance.
   !> nres: residual evaluations (each one W).
   subroutine dw_solve(v, params, a_star, state, status, nres)
      type(dw_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), intent(out) :: state
      integer, intent(out) :: status, nres
      type(contact_geometry) :: geo
      real(wp) :: g_top, s
      status = wa_ok
      nres = 0
      geo = geometry(a_star)
      if (a_star == 0.5_wp .or. params%sigma0 == 0.0_wp) then
         state = case2_state(params, geo)
         if (a_star == 0.5_wp) state%zone_case = zone_full_contact
         return
      end if
      g_top = residual(v, params, geo, 0.0_wp, nres)
      if (g_top <= 0.0_wp) then
         state = case2_state(params, geo)
         return
      end if
      call solve_case1(v, params, geo, g_top, s, status, nres)
      if (status /= wa_ok) return
      state = case1_state(params, geo, s)
   end subroutine dw_solve

   function residual(v, params, geo, u, nres) result(g)
      type(dw_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: u
      integer, intent(inout) :: nres
      real(wp) :: g
      real(wp), parameter :: lo = 1.0e-75_wp, hi = 1.0e75_wp
      real(wp) :: c, d2, omc2, inv_lambda, k, w
      nres = nres + 1
      call zone_of(geo, exp(u), c, d2, omc2)
      inv_lambda = 2.0_wp*sqrt(geo%one_minus_a2)*sqrt(d2)/params%sigma0
      k = 4.0_wp*params%sigma0**2/(pi*params%alpha**2*geo%one_minus_a2)
      w = w_of(v, geo%a, c, d2, omc2)
      if (min(k, d2, w) >= lo .and. max(k, d2, w, inv_lambda) <= hi) then
         g = log(k*d2*w*(1.0_wp + inv_lambda))
      else
         g = log(k) + log(d2) + log(w) + log1p(inv_lambda)
      end if
   end function residual

   !> W by the variant's method (NaN where it fails).
   function w_of(v, a, c, d2, omc2) result(w)
      type(dw_variant), intent(in) :: v
      real(wp), intent(in) :: a, c, d2, omc2
      real(wp) :: w
      integer :: st
      select case (v%w_method)
      case (w_agm)
         w = istar_scaled(a, c, d2, omc2)
      case (w_carlson)
         if (omc2 == 0.0_wp) then            ! R_F etc. diverge at C = 1: (E3) instead
            w = ia_star(a, d2)/d2**2
         else
            call istar_carlson(a, c, d2, omc2, w, st)
         end if
      case (w_tanh_sinh)
         call istar_quadrature(a, c, w, st, rtol=v%w_tol)
      case (w_qag)
         w = w_gsl_qag(a, c, d2, omc2, v%w_tol)
      case default
         w = ieee_value(w, ieee_quiet_nan)
      end select
   end function w_of

   !> GSL QAG (GK21) of (E1): int_0^(pi/2) s^2 k^2 sqrt(a1 k^2 + b1 s^2)/sqrt(a2 k^2 + b2 s^2).
   function w_gsl_qag(a, c, d2, omc2, tol) result(w)
      real(wp), intent(in) :: a, c, d2, omc2, tol
      real(wp) :: w
      type(e1_coef), target :: coef
      type(gsl_function) :: f
      type(c_ptr) :: work
      real(c_double) :: err
      integer(c_int) :: st
      integer(c_size_t), parameter :: limit = 200
      coef = e1_coef(omc2, d2 + omc2, c**2, a**2)
      work = gsl_integration_workspace_alloc(limit)
      f%function = c_funloc(e1_integrand)
      f%params = c_loc(coef)
      st = gsl_integration_qag(f, 0.0_c_double, real(0.5_wp*pi, c_double), 0.0_c_double, &
         max(tol, 1.2e-14_wp), limit, 2_c_int, work, w, err)
      call gsl_integration_workspace_free(work)
   end function w_gsl_qag

   function e1_integrand(phi, ctx) result(f) bind(C)
      real(c_double), value :: phi
      type(c_ptr), value :: ctx
      real(c_double) :: f
      type(e1_coef), pointer :: q
      real(wp) :: s, k
      call c_f_pointer(ctx, q)
      s = sin(phi)
      k = cos(phi)
      f = (s*k)**2*sqrt(q%a1*k**2 + q%b1*s**2)/sqrt(q%a2*k**2 + q%b2*s**2)
   end function e1_integrand

   pure function geometry(a_star) result(geo)
      real(wp), intent(in) :: a_star
      type(contact_geometry) :: geo
      geo%a_star = a_star
      call sincos_pi(a_star, geo%a, geo%cos_a)
      geo%one_minus_a2 = geo%cos_a**2
      geo%one_minus_a = geo%one_minus_a2/(1.0_wp + geo%a)
   end function geometry

   pure subroutine zone_of(geo, s, c, d2, omc2)
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: s
      real(wp), intent(out) :: c, d2, omc2
      real(wp) :: d
      if (s >= 1.0_wp) then
         c = 1.0_wp
         d2 = geo%one_minus_a2
         omc2 = 0.0_wp
         return
      end if
      d = s*geo%one_minus_a
      c = min(1.0_wp, geo%a + d)
      d2 = d*(2.0_wp*geo%a + d)
      omc2 = (1.0_wp - s)*geo%one_minus_a*(1.0_wp + c)
   end subroutine zone_of

   subroutine solve_case1(v, params, geo, g_top, s, status, nres)
      type(dw_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: g_top
      real(wp), intent(out) :: s
      integer, intent(out) :: status
      integer, intent(inout) :: nres
      real(wp), parameter :: step = log(4.0_wp), u_floor = log(tiny(1.0_wp))
      real(wp) :: u_lo, g_lo, u_hi, g_hi, u0
      u0 = log(2.0_wp*params%alpha**2*geo%cos_a/params%sigma0**2) - log(geo%one_minus_a)
      u_hi = 0.0_wp
      g_hi = g_top
      u_lo = min(u0, log(0.5_wp))
      g_lo = residual(v, params, geo, u_lo, nres)
      do while (g_lo > 0.0_wp)
         u_hi = u_lo; g_hi = g_lo
         u_lo = u_lo - step
         if (u_lo < u_floor) then
            s = 0.0_wp
            status = wa_no_solution
            return
         end if
         g_lo = residual(v, params, geo, u_lo, nres)
      end do
      if (u_hi == 0.0_wp .and. u_lo + step < 0.0_wp) then
         g_hi = residual(v, params, geo, u_lo + step, nres)
         if (g_hi >= 0.0_wp) then
            u_hi = u_lo + step
         else
            u_lo = u_lo + step; g_lo = g_hi; g_hi = g_top
         end if
      end if
      call refine(v, params, geo, u_lo, g_lo, u_hi, g_hi, s, status, nres)
   end subroutine solve_case1

   subroutine refine(v, params, geo, u1, g1, u2, g2, s, status, nres)
      type(dw_variant), intent(in) :: v
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: u1, g1, u2, g2
      real(wp), intent(out) :: s
      integer, intent(out) :: status
      integer, intent(inout) :: nres
      type(brent_type) :: solver
      real(wp) :: u
      logical :: done
      integer :: iter
      call brent_init(solver, u1, g1, u2, g2, v%xtol)
      done = .false.
      do iter = 1, max_iterations
         call brent_propose(solver, u, done)
         if (done) exit
         call brent_accept(solver, residual(v, params, geo, u, nres))
      end do
      s = exp(solver%b)
      status = merge(wa_ok, wa_not_converged, done)
   end subroutine refine

   pure function case1_state(params, geo, s) result(state)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      real(wp), intent(in) :: s
      type(state_type) :: state
      real(wp) :: c, d2, omc2, cos_c
      call zone_of(geo, s, c, d2, omc2)
      cos_c = sqrt(omc2)
      state%gap_width = atan2(d2/(c*geo%cos_a + geo%a*cos_c), cos_c*geo%cos_a + c*geo%a)/pi
      state%a_star = geo%a_star
      state%c_star = geo%a_star + state%gap_width
      state%p_star = geo%a**2 - 0.5_wp*params%sigma0*sqrt(d2/geo%one_minus_a2)
      state%zone_case = zone_inside
   end function case1_state

   pure function case2_state(params, geo) result(state)
      type(params_type), intent(in) :: params
      type(contact_geometry), intent(in) :: geo
      type(state_type) :: state
      state%a_star = geo%a_star
      state%c_star = 0.5_wp
      state%gap_width = 0.5_wp - geo%a_star
      state%p_star = geo%a**2 - 0.5_wp*params%sigma0
      state%zone_case = zone_whole_period
   end function case2_state

end module wa_study_dw
