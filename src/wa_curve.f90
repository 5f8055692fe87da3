!> display: none
!>
!> The case-1 equilibrium curve of each cohesive model as the zero set of one residual
!> F(a*, y) in the model's zone variable y, for the continuation driver (wa_branch).
!>   DW: y = ln((C - A)/(1 - A)), y_max = 0 (c* = 1/2), F = dw_residual   (2.25b)
!>   MD: y = ln((c* - a*)/(1/2 - a*)), y_max = 0, F = ln(opening/Dcod)   (2.27b)
!> (each variable makes its curve cross y_max transversally: DW's residual is smooth in
!> C, MD's opening in 1/2 - c*).
!> Case 2 (c* = 1/2) holds where F(a*, y_max) < 0; its load is A^2 - Sigma0/2 (DW),
!> A^2 - Sigma0 (MD, the extension of doc/theory.md).
module wa_curve
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, model_westergaard, model_jkr, model_dw, &
      model_md
   use wa_dw, only: dw_residual, dw_state_at, dw_load_at
   use wa_md, only: md_curve_residual, md_curve_state, md_curve_values
   use wa_models, only: model_roots, max_model_roots
   implicit none
   private

   public :: curve_residual, curve_state, curve_load, curve_values, curve_y_max, curve_weight, &
      curve_case2_load

   !> y where c* = 1/2, in both models' variables.
   real(wp), parameter :: curve_y_max = 0.0_wp
   public :: curve_variable, curve_equilibrium

contains

   !> F(a*, y): negative below the case-1 root in y, zero on the curve.
   pure function curve_residual(model, params, a_star, y) result(f)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, y
      real(wp) :: f
      if (params%sigma0 == 0.0_wp) then      ! mu = 0: Westergaard, case 2 throughout
         f = -1.0_wp
         return
      end if
      select case (model)
      case (model_dw)
         f = dw_residual(params, a_star, y)
      case (model_md)
         f = md_curve_residual(params, a_star, y)
      case default
         f = ieee_value(f, ieee_quiet_nan)
      end select
   end function curve_residual

   !> The case-1 state (c*, P*) at (a*, y).
   pure function curve_state(model, params, a_star, y) result(state)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, y
      type(state_type) :: state
      select case (model)
      case (model_dw)
         state = dw_state_at(params, a_star, y)
      case (model_md)
         state = md_curve_state(params, a_star, y)
      case default
         state%p_star = ieee_value(state%p_star, ieee_quiet_nan)
      end select
   end function curve_state

   !> curve_residual and curve_load at (a*, y) together (MD shares its geometry and zone
   !> variable between them): the values of the two functions, bit for bit.
   pure subroutine curve_values(model, params, a_star, y, f, p)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, y
      real(wp), intent(out) :: f, p
      if (model == model_md) then
         call md_curve_values(params, a_star, y, f, p)
      else
         f = curve_residual(model, params, a_star, y)
         p = curve_load(model, params, a_star, y)
      end if
   end subroutine curve_values

   !> P* of curve_state alone (DW: without its mean gap).
   pure real(wp) function curve_load(model, params, a_star, y)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, y
      type(state_type) :: state
      if (model == model_dw) then
         curve_load = dw_load_at(params, a_star, y)
      else
         state = curve_state(model, params, a_star, y)
         curve_load = state%p_star
      end if
   end function curve_load


   !> Scale of y in the arclength, so that a* and w y vary alike along the curve.
   pure real(wp) function curve_weight(model)
      integer, intent(in) :: model
      curve_weight = 0.02_wp
   end function curve_weight

   !> Case-2 load: DW A^2 - Sigma0/2 (2.28a); MD A^2 - Sigma0 (extension, doc/theory.md).
   pure real(wp) function curve_case2_load(model, params, a_star)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      curve_case2_load = sin(pi*a_star)**2 - 0.5_wp*params%sigma0
      if (model == model_md) curve_case2_load = sin(pi*a_star)**2 - params%sigma0
   end function curve_case2_load

   !> The curve variable y of a case-1 state.
   pure real(wp) function curve_variable(model, s)
      integer, intent(in) :: model
      type(state_type), intent(in) :: s
      curve_variable = zone_variable(model, s)
   end function curve_variable

   !> The equilibrium at a* on the branch through c_hint: of every state there
   !> (model_roots: one for DW, Westergaard, JKR; MD may have several), the one whose c*
   !> is nearest c_hint.
   pure subroutine curve_equilibrium(model, params, a_star, c_hint, state, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star, c_hint
      type(state_type), intent(out) :: state
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: states(max_model_roots)
      integer :: n
      call model_roots(model, params, a_star, states, n, status, errmsg)
      if (status /= wa_ok) return
      state = states(minloc(abs(states(1:n)%c_star - c_hint), dim=1))
   end subroutine curve_equilibrium

   !> y of a case-1 state; C - A = 2 cos(pi (a*+c*)/2) sin(pi (c*-a*)/2) avoids cancellation.
   pure real(wp) function zone_variable(model, s)
      integer, intent(in) :: model
      type(state_type), intent(in) :: s
      real(wp) :: c_minus_a, one_minus_a
      c_minus_a = 2.0_wp*cos(0.5_wp*pi*(s%a_star + s%c_star))*sin(0.5_wp*pi*s%gap_width)
      one_minus_a = 2.0_wp*sin(0.5_wp*pi*(0.5_wp - s%a_star))**2
      zone_variable = log(c_minus_a/one_minus_a)
      if (model == model_md) zone_variable = log(s%gap_width/(0.5_wp - s%a_star))
   end function zone_variable

end module wa_curve
