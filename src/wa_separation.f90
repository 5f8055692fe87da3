!> Separation of a solved state (doc/theory.md, "Separation"): the traction p(x)/p* and
!> the gap h(x)/Delta over one period (crest at x* = 0) and the mean gap gbar* = gbar/Delta,
!> for every model and zone case, the MD states without contact (zone case 0) among them
!> (those states themselves, the family and its closures, are wa_md_nocontact's).
!>
!> In units of Delta and p* (x* = x/L, S = sin(pi x*), A = sin(pi a*), C = sin(pi c*),
!> q = cos(pi a*), r = sqrt(S^2 - A^2), h_W(a) the Westergaard gap of wa_kernels):
!>   Westergaard  h = h_W(a),                         gbar = 1 - A^2 + A^2 ln A^2
!>   JKR          h = h_W(a) + 2 (A^2 - P*) asinh(r/A), gbar = 1 - A^2 + P* ln A^2
!>   DW           h = (1+lambda) h_W(a) - lambda h_W(c),
!>                gbar = (1+lambda) g_W(A^2) - lambda g_W(C^2)
!>   MD           h = h_W(a) - 2 Sigma0 int_0^phi(x) ln|sin(thc - f)/sin(thc + f)| w(f) df,
!>                tan phi = r/cos(pi x*), tan thc = sqrt(C^2-A^2)/cos(pi c*),
!>                w(f) = q sin f/(pi sqrt(A^2 + q^2 sin^2 f)) (= dx*/df);
!>                gbar = g_W(A^2) - Sigma0 Phi ln A^2 - 4 Sigma0 int_a*^c* acosh(sin(pi t)/A) dt
!>   MD, no contact (a* = 0, zone |x*| < c*, P* = -2 Sigma0 c*):
!>                h = h_00 + 2 S^2 - (Sigma0/pi) [Cl2(2pi(x*+c*)) - Cl2(2pi(x*-c*)) - 2 Cl2(2pi c*)],
!>                h_00 = 2 Dcod - 2 C^2 + (Sigma0/pi) [Cl2(4 pi c*) - 2 Cl2(2 pi c*)]  (h(c) = 2 Dcod),
!>                gbar = h_00 + 1 + (2 Sigma0/pi) Cl2(2 pi c*);  at c* = 1/2 the crest gap h_00
!>                is free in [0, 2 Dcod - 2] (P* = -Sigma0) and is stored as gbar - 1.
!> Full contact (zone case 3): traction P* + cos(2 pi x*), gap 0, gbar 0.
module wa_separation
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_negative_inf, &
      ieee_is_finite
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, set_error
   use wa_validate, only: check_range
   use wa_params, only: params_type, check_params
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact, &
      zone_no_contact, model_westergaard, model_jkr, model_dw, model_md
   use wa_gsl, only: gsl_sf_clausen
   use wa_math, only: log1p, sin_pi_sum, sqrt_sin_pi, sqrt_sin_pi_sum
   use wa_kernels, only: small_contact_gap, sqrt_tiny, shape
   use wa_quadrature, only: gl_x => gl16_x, gl_w => gl16_w
   implicit none
   private

   public :: westergaard_mean_gap, jkr_mean_gap, dw_state_gbar, md_state_gbar, dw_mean_gap
   public :: state_mean_gap, state_profile, state_traction, state_gap, check_state
   !> for wa_md_nocontact: the closed forms of the no-contact crest gap and Cl2(2 pi c*)
   public :: no_contact_crest, no_contact_clausen

   !> What a profile needs of a state, computed once (x-independent).
   type :: separation_context
      integer :: model = model_westergaard, zone = zone_inside
      real(wp) :: a_star = 0.0_wp, c_star = 0.0_wp, width = 0.0_wp, p_star = 0.0_wp
      real(wp) :: sigma0 = 0.0_wp, dcod = 0.0_wp
      !> A, q = cos(pi a*), C, qc = cos(pi c*), d2 = C^2 - A^2, chi1 = sqrt(d2)
      real(wp) :: a = 0.0_wp, q = 0.0_wp, c = 0.0_wp, qc = 0.0_wp, d2 = 0.0_wp, chi1 = 0.0_wp
      !> DW: lambda and lambda d2; MD: theta_c and pi/2 - theta_c; no contact: crest gap
      real(wp) :: lambda = 0.0_wp, lambda_d2 = 0.0_wp
      real(wp) :: thc = 0.0_wp, thc_c = 0.0_wp
      real(wp) :: crest = 0.0_wp
      !> 1/2 - c* = (1/2 - a*) - (c* - a*), accurate where c* is near 1/2
      real(wp) :: hmc = 0.0_wp
   end type separation_context

   !> Tanh-sinh step and half-range (|t| <= ts_range): 2 ts_range/ts_step + 1 nodes.
   real(wp), parameter :: ts_step = 1.0_wp/16.0_wp, ts_range = 3.4_wp
   !> Panels of the graded rules grow by this factor away from the near-singularity.
   real(wp), parameter :: grade = 4.0_wp
   integer, parameter :: max_panels = 400

contains

   ! ================================================================ mean gap

   !> Westergaard mean gap gbar* = 1 - A^2 + A^2 ln A^2 = g_W(P*), P* = sin^2(pi a*);
   !> NaN outside [0, 1/2].
   elemental function westergaard_mean_gap(a_star) result(g)
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      real(wp) :: g
      if (.not. (a_star >= 0.0_wp .and. a_star <= 0.5_wp)) then
         g = ieee_value(g, ieee_quiet_nan)
         return
      end if
      g = gw_of(sin(pi*a_star)**2, sin(pi*(0.5_wp - a_star))**2)
   end function westergaard_mean_gap

   !> JKR mean gap gbar* = 1 - A^2 + P* ln A^2, P* = A^2 - alpha sqrt(tan(pi a*)):
   !> Westergaard plus the flat-punch (square-root singular) term. 0 at a* = 1/2, 1 at a* = 0;
   !> NaN outside [0, 1/2] or for alpha < 0.
   elemental function jkr_mean_gap(alpha, a_star) result(g)
      !> Johnson's parameter alpha (dimensionless, (2.21)), >= 0 and finite (NaN result
      !> otherwise)
      real(wp), intent(in) :: alpha
      !> Contact half-width over the period, a* = a/L, in [0, 1/2] (NaN result outside)
      real(wp), intent(in) :: a_star
      real(wp) :: g
      real(wp) :: a, q
      if (.not. (a_star >= 0.0_wp .and. a_star <= 0.5_wp .and. alpha >= 0.0_wp .and. &
            alpha <= huge(alpha))) then
         g = ieee_value(g, ieee_quiet_nan)
         return
      end if
      if (a_star == 0.0_wp) then
         g = 1.0_wp
      else if (a_star == 0.5_wp) then
         g = 0.0_wp
      else
         a = sin(pi*a_star)
         q = sin(pi*(0.5_wp - a_star))
         ! g_W(A^2) + (P* - A^2) ln A^2, with ln A^2 = log1p(-q^2)
         g = gw_of(a*a, q*q) - alpha*sqrt(a/q)*log_a2(a, q)
      end if
   end function jkr_mean_gap

   !> DW mean gap of a solved state (zone cases 1-3): (1+lambda) g_W(A^2) - lambda g_W(C^2)
   !> written as g_W(A^2) + lambda [-d2 ln C^2 + A^2 (y - ln(1+y))], y = d2/A^2,
   !> d2 = C^2 - A^2: every term >= 0, no cancellation however large lambda.
   elemental function dw_state_gbar(params, state) result(g)
      !> The parameters the state was solved with
      type(params_type), intent(in) :: params
      !> A DW state of zone case 1, 2 or 3 solved for the same params (not validated:
      !> check_state; state_mean_gap validates)
      type(state_type), intent(in) :: state
      real(wp) :: g
      type(separation_context) :: ctx
      ctx = context_of(model_dw, params, state)
      g = dw_gbar(ctx)
   end function dw_state_gbar

   !> DW mean gap from the quantities the solver has at hand (A = sin(pi a*),
   !> q = cos(pi a*), C = sin(pi c*), qc = cos(pi c*), d2 = C^2 - A^2; case 2: C = 1,
   !> qc = 0, d2 = q^2), as in dw_state_gbar; 0 at full contact (q = 0).
   elemental function dw_mean_gap(sigma0, a, q, c, qc, d2) result(g)
      !> Peak adhesive stress over p*, Sigma0 = pi mu (alpha^2/32)^(1/3) >= 0 (params%sigma0;
      !> 0 gives the Westergaard mean gap)
      real(wp), intent(in) :: sigma0
      !> A = sin(pi a*), in [0, 1]
      real(wp), intent(in) :: a
      !> q = cos(pi a*), in [0, 1] (q <= 0: full contact, result 0)
      real(wp), intent(in) :: q
      !> C = sin(pi c*), in [A, 1] (1 in case 2)
      real(wp), intent(in) :: c
      !> qc = cos(pi c*), in [0, 1] (0 in case 2)
      real(wp), intent(in) :: qc
      !> d2 = C^2 - A^2 >= 0, formed without cancellation (q^2 in case 2; 0 gives the
      !> Westergaard mean gap)
      real(wp), intent(in) :: d2
      real(wp) :: g, lambda
      g = 0.0_wp
      if (q <= 0.0_wp) return
      g = gw_of(a*a, q*q)
      if (d2 <= 0.0_wp .or. sigma0 == 0.0_wp) return
      if (qc == 0.0_wp) then                 ! case 2: (1+lambda) g_W(A^2), lambda = Sigma0/(2q^2)
         g = (1.0_wp + sigma0/(2.0_wp*q*q))*g
         return
      end if
      lambda = sigma0/(2.0_wp*q*sqrt(d2))
      g = g + lambda*(d2*(-log_a2(c, qc)) + a2_excess(a, d2))
   end function dw_mean_gap

   !> MD mean gap of a solved state (zone cases 0-3); the quadrature of
   !> int acosh(sin(pi t)/A) dt is a graded 16-point Gauss-Legendre sum.
   elemental function md_state_gbar(params, state) result(g)
      !> The parameters the state was solved with
      type(params_type), intent(in) :: params
      !> An MD state of zone case 0-3 solved for the same params (not validated:
      !> check_state; state_mean_gap validates)
      type(state_type), intent(in) :: state
      real(wp) :: g
      type(separation_context) :: ctx
      ctx = context_of(model_md, params, state)
      g = md_gbar(ctx)
   end function md_state_gbar

   !> Mean gap gbar* of a solved state of `model`, with validation (check_state).
   pure subroutine state_mean_gap(model, params, state, gbar, status, errmsg)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> A state solved for this model and params (by model_equilibrium, model_roots, ...)
      type(state_type), intent(in) :: state
      !> Receives the mean gap over one period over Delta, gbar* (0 at full contact); 0 on
      !> failure
      real(wp), intent(out) :: gbar
      !> wa_ok; wa_invalid_argument when model, params or state fail check_state;
      !> wa_no_solution when gbar* is not finite
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(separation_context) :: ctx

      gbar = 0.0_wp
      call check_state(model, params, state, status, errmsg)
      if (status /= wa_ok) return
      ctx = context_of(model, params, state)
      gbar = gbar_of(ctx)
      if (.not. ieee_is_finite(gbar)) then
         call set_error(wa_no_solution, "gbar: not finite for this state", status, errmsg)
         gbar = 0.0_wp
      end if
   end subroutine state_mean_gap

   ! ================================================================ profiles

   !> Traction p/p* and gap h/Delta of a solved state of `model` at every x_star (any real:
   !> the period is 1, crest at 0). traction and gap must have the size of x_star.
   !> JKR: the traction is -Infinity exactly at the contact edges |x*| = a* (the square-root
   !> singularity); everything else is finite.
   pure subroutine state_profile(model, params, state, x_star, traction, gap, status, errmsg)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> A state solved for this model and params (by model_equilibrium, model_roots, ...)
      type(state_type), intent(in) :: state
      !> The points x* = x/L (any finite values: period 1, crest at 0)
      real(wp), intent(in) :: x_star(:)
      !> Receives the traction p/p* at each x_star (size(x_star); negative = tensile); all 0
      !> on failure
      real(wp), intent(out) :: traction(:)
      !> Receives the gap h/Delta at each x_star (size(x_star); 0 inside the contact); all 0
      !> on failure
      real(wp), intent(out) :: gap(:)
      !> wa_ok; wa_invalid_argument for sizes that differ from size(x_star), a non-finite
      !> x_star, or model, params or state that fail check_state
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(separation_context) :: ctx
      integer :: i

      traction = 0.0_wp
      gap = 0.0_wp
      if (size(traction) /= size(x_star) .or. size(gap) /= size(x_star)) then
         call set_error(wa_invalid_argument, "traction, gap: need the size of x_star", &
            status, errmsg)
         return
      end if
      call check_state(model, params, state, status, errmsg)
      if (status /= wa_ok) return
      do i = 1, size(x_star)
         if (.not. ieee_is_finite(x_star(i))) then
            call set_error(wa_invalid_argument, "x_star: every value must be finite", &
               status, errmsg)
            return
         end if
      end do
      ctx = context_of(model, params, state)
      do i = 1, size(x_star)
         traction(i) = traction_at(ctx, reduced(x_star(i)))
         gap(i) = gap_at(ctx, reduced(x_star(i)))
      end do
   end subroutine state_profile

   !> Traction p/p* at x* of a solved state (no validation: NaN where the state or x* is
   !> not valid; state_profile validates).
   elemental function state_traction(model, params, state, x_star) result(p)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md); NaN result
      !> for any other
      integer, intent(in) :: model
      !> The parameters the state was solved with (NaN result if they fail check_params)
      type(params_type), intent(in) :: params
      !> A state solved for this model and params (NaN result if it fails check_state)
      type(state_type), intent(in) :: state
      !> Position over the period, x* = x/L (any finite real: period 1, crest at 0; NaN
      !> result otherwise)
      real(wp), intent(in) :: x_star
      real(wp) :: p
      integer :: status
      call check_state(model, params, state, status)
      if (status /= wa_ok .or. .not. ieee_is_finite(x_star)) then
         p = ieee_value(p, ieee_quiet_nan)
         return
      end if
      p = traction_at(context_of(model, params, state), reduced(x_star))
   end function state_traction

   !> Gap h/Delta at x* of a solved state (NaN where the state or x* is not valid).
   elemental function state_gap(model, params, state, x_star) result(h)
      !> Model constant (model_westergaard, model_jkr, model_dw, model_md); NaN result
      !> for any other
      integer, intent(in) :: model
      !> The parameters the state was solved with (NaN result if they fail check_params)
      type(params_type), intent(in) :: params
      !> A state solved for this model and params (NaN result if it fails check_state)
      type(state_type), intent(in) :: state
      !> Position over the period, x* = x/L (any finite real: period 1, crest at 0; NaN
      !> result otherwise)
      real(wp), intent(in) :: x_star
      real(wp) :: h
      integer :: status
      call check_state(model, params, state, status)
      if (status /= wa_ok .or. .not. ieee_is_finite(x_star)) then
         h = ieee_value(h, ieee_quiet_nan)
         return
      end if
      h = gap_at(context_of(model, params, state), reduced(x_star))
   end function state_gap

   !> wa_ok if `state` can be a solved state of `model` (ranges and zone case; the
   !> equilibrium equation itself is not re-checked), else wa_invalid_argument.
   pure subroutine check_state(model, params, state, status, errmsg)
      !> Model constant to check (model_westergaard, model_jkr, model_dw, model_md)
      integer, intent(in) :: model
      !> Parameters to check as new_params does (check_params)
      type(params_type), intent(in) :: params
      !> The state to check: a* in [0, 1/2], c* in [a*, 1/2], c* - a* in [0, 1/2 - a*], a
      !> zone case that fits the model and a*, a finite P*
      type(state_type), intent(in) :: state
      !> wa_ok, or wa_invalid_argument for the first check that fails
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument or field and its valid range)
      character(len=*), intent(inout), optional :: errmsg

      select case (model)
      case (model_westergaard, model_jkr, model_dw, model_md)
      case default
         call set_error(wa_invalid_argument, "model: not one of 0 (westergaard), 1 (jkr), "// &
            "2 (dw), 3 (md)", status, errmsg)
         return
      end select
      call check_params(params, status, errmsg)
      if (status /= wa_ok) return
      call check_range("state%a_star", state%a_star, 0.0_wp, 0.5_wp, "[0, 1/2]", status, errmsg)
      if (status /= wa_ok) return
      call check_range("state%c_star", state%c_star, state%a_star, 0.5_wp, "[a_star, 1/2]", &
         status, errmsg)
      if (status /= wa_ok) return
      call check_range("state%gap_width", state%gap_width, 0.0_wp, 0.5_wp - state%a_star, &
         "[0, 1/2 - a_star]", status, errmsg)
      if (status /= wa_ok) return
      select case (state%zone_case)
      case (zone_no_contact)
         if (model /= model_md .or. state%a_star /= 0.0_wp) then
            call set_error(wa_invalid_argument, "state%zone_case = 0 (no contact) needs "// &
               "model md and a_star = 0", status, errmsg)
         else if (state%c_star == 0.5_wp .and. .not. (state%gbar >= 1.0_wp .and. &
               state%gbar <= 2.0_wp*params%dcod - 1.0_wp)) then
            call set_error(wa_invalid_argument, "state%gbar: a no-contact state with c_star "// &
               "= 1/2 is identified by gbar in [1, 2 Dcod - 1]", status, errmsg)
         end if
      case (zone_inside, zone_whole_period)
         if (state%a_star == 0.0_wp .and. model /= model_westergaard .and. &
               model /= model_jkr) then
            call set_error(wa_invalid_argument, "state%a_star = 0 with contact: only "// &
               "westergaard and jkr (the touching state)", status, errmsg)
         else if (state%zone_case == zone_whole_period .and. state%c_star /= 0.5_wp) then
            call set_error(wa_invalid_argument, "state%zone_case = 2 needs c_star = 1/2", &
               status, errmsg)
         else if (state%a_star == 0.5_wp) then
            call set_error(wa_invalid_argument, "state%a_star = 1/2 is full contact: "// &
               "zone_case must be 3", status, errmsg)
         end if
      case (zone_full_contact)
         if (state%a_star /= 0.5_wp) then
            call set_error(wa_invalid_argument, "state%zone_case = 3 (full contact) needs "// &
               "a_star = 1/2", status, errmsg)
         end if
      case default
         call set_error(wa_invalid_argument, "state%zone_case: not one of 0, 1, 2, 3", &
            status, errmsg)
      end select
      if (status /= wa_ok) return
      if (.not. ieee_is_finite(state%p_star)) then
         call set_error(wa_invalid_argument, "state%p_star: not finite (JKR full contact "// &
            "has no threshold load)", status, errmsg)
      end if
   end subroutine check_state

   ! ================================================================ internals

   !> x* folded into [0, 1/2].
   elemental function reduced(x_star) result(xr)
      real(wp), intent(in) :: x_star
      real(wp) :: xr
      xr = abs(x_star - anint(x_star))
   end function reduced

   !> g_W(s) = 1 - s + s ln s from s = A^2 and eps = 1 - s = q^2, both given accurately
   !> (as s -> 1: sum eps^k/(k(k-1))).
   elemental function gw_of(s, eps) result(g)
      real(wp), intent(in) :: s, eps
      real(wp) :: g, term
      integer :: k
      if (eps >= 0.1_wp) then
         g = eps
         if (s > 0.0_wp) g = eps + s*log(s)
         return
      end if
      g = 0.0_wp
      term = eps
      do k = 2, 120
         term = term*eps
         g = g + term/real(k*(k - 1), wp)
         if (term < 1.0e-18_wp*g) exit
      end do
   end function gw_of

   !> sin(pi (c* + v)) for v in [0, 1/2], from 1/2 - c* (ctx%hmc) past 1/2.
   elemental function sin_pi_c_plus(ctx, v) result(y)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: v
      real(wp) :: y
      if (ctx%hmc + (0.5_wp - v) >= 0.5_wp) then
         y = sin(pi*((ctx%a_star + ctx%width) + v))
      else
         y = sin(pi*(ctx%hmc + (0.5_wp - v)))
      end if
   end function sin_pi_c_plus

   !> c* - x*, with c* = a* + (c* - a*) from the accurate zone width (c_star itself may be
   !> off by half an ulp; the gap slope is log-singular at c*).
   elemental function c_minus(ctx, xr) result(d)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: xr
      real(wp) :: d
      ! from the side with the smaller operands (fewer rounding errors)
      if (ctx%hmc + abs(0.5_wp - xr) < ctx%width + abs(ctx%a_star - xr)) then
         d = (0.5_wp - xr) - ctx%hmc
      else
         d = (ctx%a_star - xr) + ctx%width
      end if
   end function c_minus

   !> ln A^2 from A = sin(pi a*) and q = cos(pi a*): 2 ln A, or ln(1 - q^2) near A = 1.
   elemental function log_a2(a, q) result(l)
      real(wp), intent(in) :: a, q
      real(wp) :: l
      if (a < 0.5_wp) then
         l = 2.0_wp*log(a)
      else
         l = log1p(-q*q)
      end if
   end function log_a2

   !> y - ln(1 + y) >= 0 without cancellation.
   !> A^2 (y - ln(1 + y)), y = d2/A^2, also where A^2 underflows or A = 0 (the a* -> 0
   !> limit d2): for y > 1e12, d2 - A (A (ln d2 - 2 ln A)) (the ln(1+y) - ln y tail is
   !> below 1e-12 relative and A^2 is never formed).
   elemental function a2_excess(a, d2) result(e)
      real(wp), intent(in) :: a, d2
      real(wp) :: e
      if (a <= 0.0_wp) then
         e = d2
      else if (d2 > 1.0e12_wp*a*a .or. a*a < tiny(a)) then
         e = d2 - a*(a*(log(d2) - 2.0_wp*log(a)))
      else
         e = a*a*y_minus_log1p(d2/(a*a))
      end if
   end function a2_excess

   elemental function y_minus_log1p(y) result(f)
      real(wp), intent(in) :: y
      real(wp) :: f, term
      integer :: k
      if (y > 0.1_wp) then
         f = y - log1p(y)
         return
      end if
      f = 0.0_wp
      term = -y
      do k = 2, 40
         term = -term*y
         f = f + term/real(k, wp)
         if (abs(term) < 1.0e-18_wp*abs(f)) exit
      end do
   end function y_minus_log1p

   !> Everything x-independent of a (valid) state.
   pure function context_of(model, params, state) result(ctx)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(state_type), intent(in) :: state
      type(separation_context) :: ctx

      ctx%model = model
      ctx%zone = state%zone_case
      ctx%a_star = state%a_star
      ctx%c_star = state%c_star
      ctx%width = state%gap_width
      ctx%p_star = state%p_star
      ctx%sigma0 = params%sigma0
      ctx%dcod = params%dcod
      ctx%a = sin(pi*state%a_star)
      ctx%q = sin(pi*(0.5_wp - state%a_star))
      ctx%hmc = max(0.0_wp, (0.5_wp - state%a_star) - state%gap_width)
      if (state%c_star == 0.5_wp) ctx%hmc = 0.0_wp
      ctx%c = cos(pi*ctx%hmc)
      if (ctx%hmc > 0.25_wp) ctx%c = sin(pi*(state%a_star + state%gap_width))
      ctx%qc = sin(pi*ctx%hmc)
      ! C^2 - A^2 = sin(pi (c*-a*)) sin(pi (c*+a*))
      ctx%d2 = sin(pi*state%gap_width)*sin_pi_c_plus(ctx, state%a_star)
      if (state%c_star == 0.5_wp) ctx%d2 = ctx%q**2
      ctx%chi1 = sqrt(ctx%d2)
      if (ctx%zone == zone_no_contact) then
         if (state%c_star == 0.5_wp) then
            ctx%crest = state%gbar - 1.0_wp
         else
            ctx%crest = no_contact_crest(params, state%c_star)
         end if
      end if
      if (model == model_dw .and. ctx%d2 > 0.0_wp .and. ctx%zone /= zone_full_contact) then
         ctx%lambda = params%sigma0/(2.0_wp*ctx%q*ctx%chi1)      ! (2.25b)
         ctx%lambda_d2 = 0.5_wp*params%sigma0*ctx%chi1/ctx%q
      end if
      if (model == model_md) then
         ctx%thc = atan2(ctx%chi1, ctx%qc)
         ctx%thc_c = atan2(ctx%qc, ctx%chi1)
      end if
   end function context_of

   !> Crest gap of the no-contact state at c* (no checks):
   !>   2 Dcod - 2 C^2 + (Sigma0/pi) [Cl2(4 pi c*) - 2 Cl2(2 pi c*)].
   !> The bracket is -2 Cl2(2 pi (1/2 - c*)) (duplication, Cl2(2t) = 2 Cl2(t) - 2 Cl2(pi - t));
   !> for c* >= 1/4 it is evaluated so, from the exact 1/2 - c*: the two-term form rounds
   !> 4 pi c* next to 2 pi, where Cl2 is log-singular, and Sigma0 (up to 1e22 in the domain)
   !> magnifies that error (H(1/2) came out as -2e7 instead of 2 Dcod - 2 at mu = 2.6e14).
   elemental function no_contact_crest(params, c_star) result(h)
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: c_star
      real(wp) :: h, bracket
      if (c_star >= 0.25_wp) then
         bracket = -2.0_wp*gsl_sf_clausen(2.0_wp*pi*(0.5_wp - c_star))
      else
         bracket = gsl_sf_clausen(4.0_wp*pi*c_star) - 2.0_wp*gsl_sf_clausen(2.0_wp*pi*c_star)
      end if
      h = 2.0_wp*params%dcod - 2.0_wp*sin(pi*c_star)**2 + (params%sigma0/pi)*bracket
   end function no_contact_crest

   !> Cl2(2 pi c*) for c* in [0, 1/2]. For c* >= 1/4 from d = 1/2 - c* (exact) as
   !> Cl2(2 pi d) - Cl2(4 pi d)/2 (duplication): 2 pi c* rounds next to pi, where Cl2 has
   !> slope -ln 2, and Sigma0 (up to 1e22) multiplies the result.
   elemental function no_contact_clausen(c_star) result(cl)
      real(wp), intent(in) :: c_star
      real(wp) :: cl, d
      if (c_star >= 0.25_wp) then
         d = 0.5_wp - c_star
         cl = gsl_sf_clausen(2.0_wp*pi*d) - 0.5_wp*gsl_sf_clausen(4.0_wp*pi*d)
      else
         cl = gsl_sf_clausen(2.0_wp*pi*c_star)
      end if
   end function no_contact_clausen

   !> Mean gap of any valid state.
   pure function gbar_of(ctx) result(g)
      type(separation_context), intent(in) :: ctx
      real(wp) :: g
      if (ctx%zone == zone_full_contact) then
         g = 0.0_wp
         return
      end if
      select case (ctx%model)
      case (model_westergaard)
         g = gw_of(ctx%a**2, ctx%q**2)
      case (model_jkr)
         if (ctx%a_star == 0.0_wp) then
            g = 1.0_wp
         else
            g = gw_of(ctx%a**2, ctx%q**2) + (ctx%p_star - ctx%a**2)*log_a2(ctx%a, ctx%q)
         end if
      case (model_dw)
         g = dw_gbar(ctx)
      case default
         g = md_gbar(ctx)
      end select
   end function gbar_of

   pure function dw_gbar(ctx) result(g)
      type(separation_context), intent(in) :: ctx
      real(wp) :: g
      if (ctx%zone == zone_full_contact .or. ctx%a_star == 0.5_wp) then
         g = 0.0_wp
         return
      end if
      g = gw_of(ctx%a**2, ctx%q**2)
      if (ctx%d2 > 0.0_wp) g = g + ctx%lambda_d2*(-log_a2(ctx%c, ctx%qc)) &
         + ctx%lambda*a2_excess(ctx%a, ctx%d2)
   end function dw_gbar

   pure function md_gbar(ctx) result(g)
      type(separation_context), intent(in) :: ctx
      real(wp) :: g, phi
      if (ctx%zone == zone_full_contact .or. ctx%a_star == 0.5_wp) then
         g = 0.0_wp
      else if (ctx%zone == zone_no_contact) then
         if (ctx%c_star == 0.5_wp) then
            g = ctx%crest + 1.0_wp
         else
            g = ctx%crest + 1.0_wp + (2.0_wp*ctx%sigma0/pi)*no_contact_clausen(ctx%c_star)
         end if
      else if (ctx%c_star == 0.5_wp .or. ctx%d2 == 0.0_wp) then
         g = gw_of(ctx%a**2, ctx%q**2)              ! case 2: uniform -Sigma0 adds no deformation
      else
         phi = (2.0_wp/pi)*ctx%thc         ! 1 - (2/pi) arcsin(cos(pi c*)/cos(pi a*))
         g = gw_of(ctx%a**2, ctx%q**2) - ctx%sigma0*(phi*log_a2(ctx%a, ctx%q) &
            + 4.0_wp*acosh_integral(ctx))
      end if
   end function md_gbar

   !> int_a*^c* acosh(sin(pi t)/A) dt = int_0^thc asinh(q sin f/A) w(f) df, graded towards
   !> f = 0 where the integrand has branch points at distance ~A/q.
   pure function acosh_integral(ctx) result(total)
      type(separation_context), intent(in) :: ctx
      real(wp) :: total
      real(wp) :: lo, hi, f, sf
      integer :: panel, i
      total = 0.0_wp
      lo = 0.0_wp
      hi = min(ctx%thc, ctx%a/ctx%q)
      do panel = 1, max_panels
         do i = 1, size(gl_x)
            f = lo + (hi - lo)*gl_x(i)
            sf = sin(f)
            total = total + (hi - lo)*gl_w(i)*asinh(ctx%q*sf/ctx%a)*weight(ctx, sf)
         end do
         if (hi >= ctx%thc) exit
         lo = hi
         hi = min(ctx%thc, grade*hi)
      end do
   end function acosh_integral

   !> dx*/dphi = q sin(phi)/(pi sqrt(A^2 + q^2 sin^2 phi))
   elemental function weight(ctx, sf) result(w)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: sf
      real(wp) :: w
      w = ctx%q*sf/(pi*sqrt(ctx%a**2 + (ctx%q*sf)**2))
   end function weight

   !> Traction p/p* at xr in [0, 1/2].
   pure function traction_at(ctx, xr) result(p)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: xr
      real(wp) :: p
      real(wp) :: cx, ra, rc, r1, r2

      p = 0.0_wp
      cx = sin(pi*(0.5_wp - xr))
      if (ctx%zone == zone_full_contact) then
         p = ctx%p_star + cos(2.0_wp*pi*xr)
         return
      end if
      if (ctx%zone == zone_no_contact) then
         if (xr <= ctx%c_star .and. ctx%c_star > 0.0_wp) p = -ctx%sigma0
         return
      end if
      ! ra = sqrt(A^2 - S^2) = r1 r2; r1 = ra, r2 = 1 unless A^2 - S^2 is subnormal or 0
      ! (a* below 1e-154), then r1, r2 = sqrt(sin(pi (a* -+ x*))), kept apart
      ra = 0.0_wp
      r2 = 1.0_wp
      if (xr < ctx%a_star) then
         ra = sin(pi*(ctx%a_star - xr))*sin_pi_sum(ctx%a_star, xr)
         if (ra >= tiny(ra)) then
            ra = sqrt(ra)
            r1 = ra
         else
            r1 = sqrt_sin_pi(ctx%a_star - xr)
            r2 = sqrt_sin_pi_sum(ctx%a_star, xr)
            ra = r1*r2
         end if
      end if
      select case (ctx%model)
      case (model_westergaard)
         if (xr < ctx%a_star) p = 2.0_wp*cx*r1*r2
      case (model_jkr)
         if (xr < ctx%a_star) then
            p = 2.0_wp*cx*r1*r2 + (ctx%p_star - ctx%a**2)*cx/r1/r2
         else if (xr == ctx%a_star .and. ctx%p_star < ctx%a**2) then
            p = ieee_value(p, ieee_negative_inf)
         end if
      case (model_dw)
         if (c_minus(ctx, xr) >= 0.0_wp) then
            rc = sqrt(max(0.0_wp, sin(pi*c_minus(ctx, xr))*sin_pi_c_plus(ctx, xr)))
            if (ctx%c_star == 0.5_wp) rc = cx
            if (xr < ctx%a_star) then
               ! (1+lambda) p_W(a) - lambda p_W(c), p_W(a) - p_W(c) = -2 cx d2/(ra + rc)
               p = 2.0_wp*cx*ra - 2.0_wp*ctx%lambda_d2*cx/(ra + rc)
            else
               p = -2.0_wp*ctx%lambda*cx*rc
            end if
         end if
      case default
         if (xr < ctx%a_star) then
            p = 2.0_wp*cx*ra - (2.0_wp*ctx%sigma0/pi)*atan2(cx*ctx%chi1, ra*ctx%qc)
         else if (c_minus(ctx, xr) >= 0.0_wp .and. ctx%c_star > ctx%a_star) then
            p = -ctx%sigma0
         end if
      end select
   end function traction_at

   !> Gap h/Delta at xr in [0, 1/2].
   pure function gap_at(ctx, xr) result(h)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: xr
      real(wp) :: h
      real(wp) :: s, r, t

      h = 0.0_wp
      if (ctx%zone == zone_full_contact) return
      s = sin(pi*xr)
      if (ctx%zone == zone_no_contact) then
         h = ctx%crest + 2.0_wp*s*s
         if (ctx%c_star > 0.0_wp .and. ctx%c_star < 0.5_wp) h = h - (ctx%sigma0/pi)* &
            (gsl_sf_clausen(2.0_wp*pi*(xr + ctx%c_star)) - gsl_sf_clausen(2.0_wp*pi* &
            (xr - ctx%c_star)) - 2.0_wp*gsl_sf_clausen(2.0_wp*pi*ctx%c_star))
         h = max(0.0_wp, h)
         return
      end if
      if (xr <= ctx%a_star) return
      if (ctx%a > 0.0_wp .and. ctx%a < sqrt_tiny .and. (ctx%model == model_westergaard .or. &
            ctx%model == model_jkr)) then
         ! A^2 subnormal or 0 (a* below 4.7e-155): t = asinh(r/A) from root ratios
         call small_contact_gap(ctx%a_star, xr, h, t)
         if (ctx%model == model_jkr) h = h + 2.0_wp*(ctx%a**2 - ctx%p_star)*t
         h = max(0.0_wp, h)
         return
      end if
      r = sqrt(sin(pi*(xr - ctx%a_star))*sin_pi_sum(xr, ctx%a_star))
      h = shape(ctx%a, s, r)
      select case (ctx%model)
      case (model_jkr)
         if (ctx%a > 0.0_wp) h = h + 2.0_wp*(ctx%a**2 - ctx%p_star)*asinh(r/ctx%a)
      case (model_dw)
         if (c_minus(ctx, xr) >= 0.0_wp) then
            h = (1.0_wp + ctx%lambda)*h
         else
            h = h + ctx%lambda*dw_difference(ctx, s, r, xr)
         end if
      case (model_md)
         if (ctx%c_star < 0.5_wp .and. ctx%d2 > 0.0_wp) h = h - 2.0_wp*ctx%sigma0* &
            md_log_integral(ctx, xr, s, r)
      end select
      h = max(0.0_wp, h)
   end function gap_at

   !> h_W(a) - h_W(c) beyond c (x* > c*), as a sum of non-negative terms and an O(d2^2)
   !> term, d2 = C^2 - A^2 (doc/theory.md): accurate however large lambda.
   pure function dw_difference(ctx, s, ra, xr) result(dd)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: s, ra, xr
      real(wp) :: dd
      real(wp) :: rc, d2, z
      d2 = ctx%d2
      rc = sqrt(max(0.0_wp, sin(-pi*c_minus(ctx, xr))*sin_pi_c_plus(ctx, xr)))
      z = d2/((ra + rc)*(s + rc))
      dd = 2.0_wp*(0.5_wp*a2_excess(ctx%a, d2) + ctx%a**2*y_minus_log1p(z) &
         + d2*d2*(2.0_wp*ra + rc - s)/(2.0_wp*(ra + rc)**2*(s + rc)) + d2*asinh(rc/ctx%c))
   end function dw_difference

   !> M(x) = int_0^phi(x) ln|sin(thc - f)/sin(thc + f)| w(f) df (<= 0) for the MD gap,
   !> h = h_W(a) - 2 Sigma0 M. Panels graded towards f = 0 (branch points at ~ iA/q),
   !> tanh-sinh on the panels that end at the log singularity f = thc.
   pure function md_log_integral(ctx, xr, s, r) result(total)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: xr, s, r
      real(wp) :: total
      real(wp) :: phx, phx_c, dx_top, top, lo, hi
      integer :: panel
      logical :: beyond

      phx = atan2(r, sin(pi*(0.5_wp - xr)))
      phx_c = atan2(sin(pi*(0.5_wp - xr)), r)
      beyond = c_minus(ctx, xr) < 0.0_wp
      ! thc - phi(x), accurately: tan = q^2 sin(pi(c-x)) sin(pi(c+x)) / (...)
      dx_top = atan2(ctx%q**2*sin(pi*c_minus(ctx, xr))*sin_pi_c_plus(ctx, xr), &
         (ctx%chi1*sin(pi*(0.5_wp - xr)) + r*ctx%qc)*(ctx%qc*sin(pi*(0.5_wp - xr)) &
         + ctx%chi1*r))
      top = merge(ctx%thc, phx, beyond)
      total = 0.0_wp
      ! graded Gauss-Legendre panels up to top/grade, then tanh-sinh on the last one
      lo = 0.0_wp
      hi = ctx%a/ctx%q
      do panel = 1, max_panels
         if (hi >= top/grade) exit
         total = total + gl_log_panel(ctx, lo, hi)
         lo = hi
         hi = grade*hi
      end do
      if (beyond) then
         total = total + right_graded(ctx, lo, ctx%thc, ctx%thc - lo, 0.0_wp, &
            0.5_wp*pi - lo, ctx%thc_c)
         ! beyond thc: tanh-sinh next to the log singularity, then Gauss-Legendre panels
         ! doubling in size (the integrand varies on the scales thc and A/q)
         if (phx <= 2.0_wp*ctx%thc) then
            total = total + ts_panel(ctx, ctx%thc, phx, 0.0_wp, dx_top, ctx%thc_c, phx_c, &
               -dx_top)
         else
            total = total + ts_panel(ctx, ctx%thc, 2.0_wp*ctx%thc, 0.0_wp, -ctx%thc, &
               ctx%thc_c, 0.5_wp*pi - 2.0_wp*ctx%thc)
            lo = 2.0_wp*ctx%thc
            do panel = 1, max_panels
               hi = min(phx, 2.0_wp*lo)
               if (hi > phx/1.5_wp) hi = phx
               total = total + gl_log_panel(ctx, lo, hi)
               if (hi >= phx) exit
               lo = hi
            end do
         end if
      else
         total = total + right_graded(ctx, lo, phx, ctx%thc - lo, dx_top, 0.5_wp*pi - lo, phx_c)
      end if
   end function md_log_integral

   !> The panel [lo, top] that ends at (or just before) the log singularity at thc; when
   !> thc is near pi/2 the second one, at pi - thc (sin(thc + f) = 0), sits 2 (pi/2 - thc)
   !> beyond it: Gauss-Legendre panels shrinking by 4 towards top down to that scale, then
   !> tanh-sinh. dlo, dtop = thc - lo, thc - top; clo, ctop = pi/2 - lo, pi/2 - top.
   pure function right_graded(ctx, lo, top, dlo, dtop, clo, ctop) result(total)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: lo, top, dlo, dtop, clo, ctop
      real(wp) :: total
      real(wp) :: d, scale
      integer :: k
      total = 0.0_wp
      scale = max(2.0_wp*ctx%thc_c + abs(dtop), tiny(1.0_wp))
      d = top - lo
      do k = 1, max_panels
         if (d <= 2.0_wp*scale) exit
         ! [top - d, top - d/4]
         total = total + gl_log_panel_d(ctx, top - d, 0.75_wp*d, dtop + d, ctop + d)
         d = 0.25_wp*d
      end do
      if (d >= top - lo) then
         total = total + ts_panel(ctx, lo, top, dlo, dtop, clo, ctop)
      else
         total = total + ts_panel(ctx, top - d, top, dtop + d, dtop, ctop + d, ctop, d)
      end if
   end function right_graded

   !> Gauss-Legendre on [f0, f0 + w] given thc - f0 and pi/2 - f0 accurately.
   pure function gl_log_panel_d(ctx, f0, w, d0, c0) result(total)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: f0, w, d0, c0
      real(wp) :: total, f
      integer :: i
      total = 0.0_wp
      do i = 1, size(gl_x)
         f = f0 + w*gl_x(i)
         total = total + gl_w(i)*log_ratio(ctx, f, d0 - w*gl_x(i), c0 - w*gl_x(i)) &
            *weight(ctx, sin(f))
      end do
      total = total*w
   end function gl_log_panel_d

   !> Gauss-Legendre on [lo, hi] (away from thc) of ln|...| w.
   pure function gl_log_panel(ctx, lo, hi) result(total)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: lo, hi
      real(wp) :: total, f
      integer :: i
      total = 0.0_wp
      do i = 1, size(gl_x)
         f = lo + (hi - lo)*gl_x(i)
         total = total + gl_w(i)*log_ratio(ctx, f, ctx%thc - f, 0.5_wp*pi - f)*weight(ctx, sin(f))
      end do
      total = total*(hi - lo)
   end function gl_log_panel

   !> Tanh-sinh on [lo, hi] of ln|sin(thc - f)/sin(thc + f)| w(f), given thc - lo, thc - hi,
   !> pi/2 - lo and pi/2 - hi accurately (a node takes them from its nearer end).
   pure function ts_panel(ctx, lo, hi, dlo, dhi, clo, chi, width) result(total)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: lo, hi, dlo, dhi, clo, chi
      !> hi - lo where the caller knows it better than by subtraction
      real(wp), intent(in), optional :: width
      real(wp) :: total
      real(wp) :: t, u, e, elo, ehi, wt, f, delta, fc, half
      integer :: k, nk
      total = 0.0_wp
      half = 0.5_wp*(hi - lo)
      if (present(width)) half = 0.5_wp*width
      if (half <= 0.0_wp) return
      nk = nint(ts_range/ts_step)
      do k = -nk, nk
         t = k*ts_step
         u = 0.5_wp*pi*sinh(t)
         e = exp(-2.0_wp*abs(u))
         ! distances from the ends: 2 half/(1 + e^{-2u}) and 2 half/(1 + e^{2u})
         if (u >= 0.0_wp) then
            elo = 2.0_wp*half/(1.0_wp + e)
            ehi = 2.0_wp*half*e/(1.0_wp + e)
         else
            elo = 2.0_wp*half*e/(1.0_wp + e)
            ehi = 2.0_wp*half/(1.0_wp + e)
         end if
         wt = half*0.5_wp*pi*cosh(t)*4.0_wp*e/(1.0_wp + e)**2
         if (elo <= ehi) then
            f = lo + elo; delta = dlo - elo; fc = clo - elo
         else
            f = hi - ehi; delta = dhi + ehi; fc = chi + ehi
         end if
         if (delta == 0.0_wp .or. wt == 0.0_wp) cycle
         total = total + wt*log_ratio(ctx, f, delta, fc)*weight(ctx, sin(f))
      end do
      total = total*ts_step
   end function ts_panel

   !> ln|sin(thc - f)/sin(thc + f)| from f, delta = thc - f and fc = pi/2 - f.
   elemental function log_ratio(ctx, f, delta, fc) result(l)
      type(separation_context), intent(in) :: ctx
      real(wp), intent(in) :: f, delta, fc
      real(wp) :: l, num, den
      if (ctx%thc + f <= 0.5_wp*pi) then
         den = sin(ctx%thc + f)
      else
         den = sin(ctx%thc_c + fc)
      end if
      num = sin(abs(delta))
      if (num < 0.5_wp*den) then
         l = log(num/den)
      else if (delta > 0.0_wp) then           ! sin(thc-f) - sin(thc+f) = -2 cos(thc) sin f
         l = log1p(-2.0_wp*sin(ctx%thc_c)*sin(f)/den)
      else                                   ! sin(f-thc) - sin(f+thc) = -2 cos(f) sin(thc)
         l = log1p(-2.0_wp*sin(fc)*sin(ctx%thc)/den)
      end if
   end function log_ratio

end module wa_separation
