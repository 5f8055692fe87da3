!> The two dimensionless parameters (alpha, mu) and what derives from them, with a
!> validating constructor and the conversion from SI inputs (doc/theory.md, "Parameters").
module wa_params
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok
   use wa_validate, only: check_range
   implicit none
   private

   public :: params_type, new_params, check_params, dimensional_params, reduced_modulus
   public :: scales_type

   !> Dimensionless model parameters.
   type :: params_type
      !> Johnson's parameter alpha = sqrt(2 dgamma L / (pi^2 E* Delta^2)) > 0
      real(wp) :: alpha = 0.0_wp
      !> Transition parameter mu = Sigma0 / (pi (alpha^2/32)^(1/3)) >= 0   (2.19) corrected
      real(wp) :: mu = 0.0_wp
      !> Peak adhesive stress over p*: Sigma0 = pi mu (alpha^2/32)^(1/3)   (2.25c)
      real(wp) :: sigma0 = 0.0_wp
      !> Maugis-Dugdale opening Dcod = (alpha^4/2)^(1/3)/mu (+Infinity at mu = 0)   (A7)
      real(wp) :: dcod = 0.0_wp
   end type params_type

   !> The accepted parameter domain. Inside it every derived quantity (Sigma0, Dcod, their
   !> squares and ratios) is a normal double and the solvers are tested (doc/theory.md,
   !> "Supported range"); outside it new_params refuses with wa_invalid_argument. mu = 0
   !> (the Westergaard limit) is accepted; 0 < mu < mu_min is refused, not rounded.
   real(wp), parameter, public :: alpha_min = 1.0e-12_wp, alpha_max = 1.0e12_wp
   real(wp), parameter, public :: mu_min = 1.0e-100_wp, mu_max = 1.0e100_wp

   !> SI scales that turn the dimensionless results back into physical ones.
   type :: scales_type
      !> Reduced modulus E* [Pa]
      real(wp) :: estar = 0.0_wp
      !> Full-contact pressure p* = pi E* Delta / L [Pa]: mean traction = P* p*
      real(wp) :: pressure = 0.0_wp
      !> Force per period and unit depth for P* = 1: p* L [N/m]
      real(wp) :: force = 0.0_wp
      !> Period L [m]: a = a* L, c = c* L
      real(wp) :: length = 0.0_wp
      !> Crest radius R = L^2 / (4 pi^2 Delta) [m]   (2.1b)
      real(wp) :: radius = 0.0_wp
   end type scales_type

contains

   !> Validating constructor: alpha in [alpha_min, alpha_max], mu = 0 or in
   !> [mu_min, mu_max] (1e-12 <= alpha <= 1e12, mu = 0 or 1e-100 <= mu <= 1e100).
   pure subroutine new_params(alpha, mu, params, status, errmsg)
      !> Johnson's parameter alpha (dimensionless, (2.21)), in [alpha_min, alpha_max]
      real(wp), intent(in) :: alpha
      !> Transition parameter mu (dimensionless, (2.19)), 0 (the Westergaard limit) or in
      !> [mu_min, mu_max]
      real(wp), intent(in) :: mu
      !> The parameters with Sigma0 and Dcod derived (default-initialised on failure)
      type(params_type), intent(out) :: params
      !> wa_ok, or wa_invalid_argument when an input is outside its range
      integer, intent(out) :: status
      !> Receives the reason on failure: the argument, its value and its valid range
      character(len=*), intent(inout), optional :: errmsg
      call check_range("alpha", alpha, alpha_min, alpha_max, "[1e-12, 1e12]", status, errmsg)
      if (status /= wa_ok) return
      if (mu /= 0.0_wp) then
         call check_range("mu", mu, mu_min, mu_max, "0 or [1e-100, 1e100]", status, errmsg)
         if (status /= wa_ok) return
      end if
      params%alpha = alpha
      params%mu = mu
      params%sigma0 = pi*mu*(alpha**2/32.0_wp)**(1.0_wp/3.0_wp)
      if (mu > 0.0_wp) then
         params%dcod = (alpha**4/2.0_wp)**(1.0_wp/3.0_wp)/mu
      else
         params%dcod = ieee_value(params%dcod, ieee_positive_inf)
      end if
   end subroutine new_params

   !> Re-validate a params_type (it may have been filled by hand): the checks of new_params.
   pure subroutine check_params(params, status, errmsg)
      type(params_type), intent(in) :: params
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(params_type) :: fresh
      call new_params(params%alpha, params%mu, fresh, status, errmsg)
   end subroutine check_params

   !> Reduced modulus 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2   (2.2b)
   pure subroutine reduced_modulus(e1, nu1, e2, nu2, estar, status, errmsg)
      !> Young's modulus of the first body [Pa], in (0, inf)
      real(wp), intent(in) :: e1
      !> Poisson ratio of the first body, in (-1, 1/2]
      real(wp), intent(in) :: nu1
      !> Young's modulus of the second body [Pa], in (0, inf)
      real(wp), intent(in) :: e2
      !> Poisson ratio of the second body, in (-1, 1/2]
      real(wp), intent(in) :: nu2
      !> The reduced modulus E* [Pa] (0 on failure)
      real(wp), intent(out) :: estar
      !> wa_ok, or wa_invalid_argument when an input is outside its range
      integer, intent(out) :: status
      !> Receives the reason on failure: the argument, its value and its valid range
      character(len=*), intent(inout), optional :: errmsg
      estar = 0.0_wp
      call check_range("E1", e1, 0.0_wp, huge(1.0_wp), "(0, inf) Pa", status, errmsg, &
         lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("E2", e2, 0.0_wp, huge(1.0_wp), "(0, inf) Pa", status, errmsg, &
         lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("nu1", nu1, -1.0_wp, 0.5_wp, "(-1, 1/2]", status, errmsg, lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("nu2", nu2, -1.0_wp, 0.5_wp, "(-1, 1/2]", status, errmsg, lo_open=.true.)
      if (status /= wa_ok) return
      estar = 1.0_wp/((1.0_wp - nu1**2)/e1 + (1.0_wp - nu2**2)/e2)
   end subroutine reduced_modulus

   !> Dimensionless parameters and SI scales from E* [Pa], period L [m], amplitude
   !> Delta [m], work of adhesion dgamma [J/m^2] and peak adhesive stress sigma0 [Pa].
   !> alpha = sqrt(2 dgamma L/(pi^2 E* Delta^2)), Sigma0 = sigma0/p*, mu from Sigma0.
   pure subroutine dimensional_params(estar, period, amplitude, work_of_adhesion, &
         peak_stress, params, scales, status, errmsg)
      !> Reduced modulus E* [Pa] (reduced_modulus), in (0, inf)
      real(wp), intent(in) :: estar
      !> Period L of the wavy surface [m], in (0, inf)
      real(wp), intent(in) :: period
      !> Amplitude Delta of the wave [m] (half the peak-to-valley height), in (0, inf)
      real(wp), intent(in) :: amplitude
      !> Work of adhesion dgamma [J/m^2], in (0, inf)
      real(wp), intent(in) :: work_of_adhesion
      !> Peak adhesive (Dugdale) stress sigma0 [Pa], in [0, inf); 0 gives mu = 0
      real(wp), intent(in) :: peak_stress
      !> The dimensionless parameters alpha, mu, Sigma0, Dcod
      type(params_type), intent(out) :: params
      !> The SI scales (E*, p*, force per period, L, crest radius R) of the results
      type(scales_type), intent(out) :: scales
      !> wa_ok, or wa_invalid_argument when an input or the alpha, mu it gives is out of range
      integer, intent(out) :: status
      !> Receives the reason on failure: the argument, its value and its valid range
      character(len=*), intent(inout), optional :: errmsg
      real(wp), parameter :: big = huge(1.0_wp)
      real(wp) :: alpha, mu, pstar

      call check_range("Estar", estar, 0.0_wp, big, "(0, inf) Pa", status, errmsg, &
         lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("period", period, 0.0_wp, big, "(0, inf) m", status, errmsg, &
         lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("amplitude", amplitude, 0.0_wp, big, "(0, inf) m", status, errmsg, &
         lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("work_of_adhesion", work_of_adhesion, 0.0_wp, big, "(0, inf) J/m^2", &
         status, errmsg, lo_open=.true.)
      if (status /= wa_ok) return
      call check_range("peak_stress", peak_stress, 0.0_wp, huge(1.0_wp), "[0, inf) Pa", &
         status, errmsg)
      if (status /= wa_ok) return

      pstar = pi*estar*amplitude/period
      alpha = sqrt(2.0_wp*work_of_adhesion*period/(pi**2*estar*amplitude**2))
      mu = (peak_stress/pstar)/(pi*(alpha**2/32.0_wp)**(1.0_wp/3.0_wp))
      call new_params(alpha, mu, params, status, errmsg)
      if (status /= wa_ok) then
         if (present(errmsg)) errmsg = "the SI inputs give "//errmsg
         return
      end if
      scales%estar = estar
      scales%pressure = pstar
      scales%force = pstar*period
      scales%length = period
      scales%radius = period**2/(4.0_wp*pi**2*amplitude)

   end subroutine dimensional_params

end module wa_params
