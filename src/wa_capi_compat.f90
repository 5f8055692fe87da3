!> display: none
!>
!> The C interface, 0.2 compatibility (removed in 0.4): the names 0.2 had besides the
!> 0.3 functions, each one line calling the core of its 0.3 function with the 0.2
!> arguments (the `_msg` twins: no mean gap; the `_gap` variants: the mean gap required,
!> no message; wa_critical_sweep_status: row_status required; wa_adhesion_map_control:
!> the 0.2 scan of 60 mu, no message). Results are those of the 0.3 functions bit for
!> bit (test/capi/main.c checks every forward). Declared in the marked block of
!> include/wavyadhesion.h; doc/c-api.md gives the migration.
module wa_capi_compat
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_null_ptr
   use wa_capi, only: equilibrium_core, roots_core, branch_core, critical_core, path_core, &
      sweep_core, profile_core
   use wa_capi_gap, only: gap_path_core, gap_law_core, gap_critical_core
   use wa_capi_map, only: map_core
   implicit none
   private

   public :: compat_equilibrium_msg, compat_roots_msg, compat_trace_branch_msg, &
      compat_critical_forces_msg, compat_load_path_msg, compat_critical_sweep_msg, &
      compat_profile_msg, compat_gap_path_msg, compat_gap_law_msg, compat_gap_critical_msg
   public :: compat_equilibrium_gap, compat_equilibrium_gap_msg, compat_roots_gap, &
      compat_roots_gap_msg, compat_trace_branch_gap, compat_trace_branch_gap_msg, &
      compat_critical_sweep_status, compat_adhesion_map_control

   !> The discovery scan of 0.2's wa_adhesion_map_control (now the argument n_mu).
   integer(c_int), parameter :: map_n_mu_02 = 60

contains

   !> 0.2 wa_equilibrium_msg: wa_equilibrium with gbar NULL.
   function compat_equilibrium_msg(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         message, message_capacity) result(status) bind(C, name="wa_equilibrium_msg")
      integer(c_int), value, intent(in) :: model, message_capacity
      real(c_double), value, intent(in) :: alpha, mu, a_star
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case, message
      integer(c_int) :: status
      status = equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         c_null_ptr, .false., message, message_capacity)
   end function compat_equilibrium_msg

   !> 0.2 wa_equilibrium_gap: wa_equilibrium with gbar required, no message.
   function compat_equilibrium_gap(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar) &
         result(status) bind(C, name="wa_equilibrium_gap")
      integer(c_int), value, intent(in) :: model
      real(c_double), value, intent(in) :: alpha, mu, a_star
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case, gbar
      integer(c_int) :: status
      status = equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar, &
         .true., c_null_ptr, 0_c_int)
   end function compat_equilibrium_gap

   !> 0.2 wa_equilibrium_gap_msg: wa_equilibrium with gbar required.
   function compat_equilibrium_gap_msg(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         gbar, message, message_capacity) result(status) bind(C, name="wa_equilibrium_gap_msg")
      integer(c_int), value, intent(in) :: model, message_capacity
      real(c_double), value, intent(in) :: alpha, mu, a_star
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case, gbar, message
      integer(c_int) :: status
      status = equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar, &
         .true., message, message_capacity)
   end function compat_equilibrium_gap_msg

   !> 0.2 wa_roots_msg: wa_roots with gbar NULL.
   function compat_roots_msg(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, message, message_capacity) result(status) bind(C, name="wa_roots_msg")
      integer(c_int), value, intent(in) :: model, capacity, message_capacity
      real(c_double), value, intent(in) :: alpha, mu, a_star
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case, n_roots, message
      integer(c_int) :: status
      status = roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         c_null_ptr, .false., n_roots, message, message_capacity)
   end function compat_roots_msg

   !> 0.2 wa_roots_gap: wa_roots with gbar required, no message.
   function compat_roots_gap(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         gbar, n_roots) result(status) bind(C, name="wa_roots_gap")
      integer(c_int), value, intent(in) :: model, capacity
      real(c_double), value, intent(in) :: alpha, mu, a_star
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case, gbar, n_roots
      integer(c_int) :: status
      status = roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         gbar, .true., n_roots, c_null_ptr, 0_c_int)
   end function compat_roots_gap

   !> 0.2 wa_roots_gap_msg: wa_roots with gbar required.
   function compat_roots_gap_msg(model, alpha, mu, a_star, capacity, c_star, p_star, &
         zone_case, gbar, n_roots, message, message_capacity) result(status) &
         bind(C, name="wa_roots_gap_msg")
      integer(c_int), value, intent(in) :: model, capacity, message_capacity
      real(c_double), value, intent(in) :: alpha, mu, a_star
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case, gbar, n_roots, message
      integer(c_int) :: status
      status = roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         gbar, .true., n_roots, message, message_capacity)
   end function compat_roots_gap_msg

   !> 0.2 wa_trace_branch_msg: wa_trace_branch with gbar NULL.
   function compat_trace_branch_msg(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, n_points, message, message_capacity) result(status) &
         bind(C, name="wa_trace_branch_msg")
      integer(c_int), value, intent(in) :: model, capacity, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star, zone_case, stable, event, &
         n_points, message
      integer(c_int) :: status
      status = branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star], c_null_ptr, &
         .false., [zone_case, stable, event], n_points, message, message_capacity)
   end function compat_trace_branch_msg

   !> 0.2 wa_trace_branch_gap: wa_trace_branch with gbar required, no message.
   function compat_trace_branch_gap(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, gbar, n_points) result(status) &
         bind(C, name="wa_trace_branch_gap")
      integer(c_int), value, intent(in) :: model, capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star, zone_case, stable, event, &
         gbar, n_points
      integer(c_int) :: status
      status = branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star], gbar, &
         .true., [zone_case, stable, event], n_points, c_null_ptr, 0_c_int)
   end function compat_trace_branch_gap

   !> 0.2 wa_trace_branch_gap_msg: wa_trace_branch with gbar required.
   function compat_trace_branch_gap_msg(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, gbar, n_points, message, message_capacity) &
         result(status) bind(C, name="wa_trace_branch_gap_msg")
      integer(c_int), value, intent(in) :: model, capacity, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star, zone_case, stable, event, &
         gbar, n_points, message
      integer(c_int) :: status
      status = branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star], gbar, &
         .true., [zone_case, stable, event], n_points, message, message_capacity)
   end function compat_trace_branch_gap_msg

   !> 0.2 wa_critical_forces_msg: wa_critical_forces.
   function compat_critical_forces_msg(model, alpha, mu, p_fc, p_pf, message, &
         message_capacity) result(status) bind(C, name="wa_critical_forces_msg")
      integer(c_int), value, intent(in) :: model, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: p_fc, p_pf, message
      integer(c_int) :: status
      status = critical_core(model, alpha, mu, p_fc, p_pf, message, message_capacity)
   end function compat_critical_forces_msg

   !> 0.2 wa_load_path_msg: wa_load_path.
   function compat_load_path_msg(model, alpha, mu, capacity, stage, event, a_star, c_star, &
         p_star, n_events, p_fc, p_pf, message, message_capacity) result(status) &
         bind(C, name="wa_load_path_msg")
      integer(c_int), value, intent(in) :: model, capacity, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: stage, event, a_star, c_star, p_star, n_events, &
         p_fc, p_pf, message
      integer(c_int) :: status
      status = path_core(model, alpha, mu, capacity, [stage, event], [a_star, c_star, p_star], &
         n_events, p_fc, p_pf, message, message_capacity)
   end function compat_load_path_msg

   !> 0.2 wa_critical_sweep_msg: wa_critical_sweep with row_status NULL.
   function compat_critical_sweep_msg(model, alpha, n_mu, mu, p_fc, p_pf, fc_mechanism, &
         pf_mechanism, message, message_capacity) result(status) &
         bind(C, name="wa_critical_sweep_msg")
      integer(c_int), value, intent(in) :: model, n_mu, message_capacity
      real(c_double), value, intent(in) :: alpha
      type(c_ptr), value, intent(in) :: mu, p_fc, p_pf, fc_mechanism, pf_mechanism, message
      integer(c_int) :: status
      status = sweep_core(model, alpha, n_mu, mu, [p_fc, p_pf], [fc_mechanism, pf_mechanism], &
         c_null_ptr, .false., message, message_capacity)
   end function compat_critical_sweep_msg

   !> 0.2 wa_critical_sweep_status: wa_critical_sweep with row_status required.
   function compat_critical_sweep_status(model, alpha, n_mu, mu, p_fc, p_pf, fc_mechanism, &
         pf_mechanism, row_status, message, message_capacity) result(status) &
         bind(C, name="wa_critical_sweep_status")
      integer(c_int), value, intent(in) :: model, n_mu, message_capacity
      real(c_double), value, intent(in) :: alpha
      type(c_ptr), value, intent(in) :: mu, p_fc, p_pf, fc_mechanism, pf_mechanism, &
         row_status, message
      integer(c_int) :: status
      status = sweep_core(model, alpha, n_mu, mu, [p_fc, p_pf], [fc_mechanism, pf_mechanism], &
         row_status, .true., message, message_capacity)
   end function compat_critical_sweep_status

   !> 0.2 wa_profile_msg: wa_profile.
   function compat_profile_msg(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         message, message_capacity) result(status) bind(C, name="wa_profile_msg")
      integer(c_int), value, intent(in) :: model, n, message_capacity
      real(c_double), value, intent(in) :: alpha, mu, a_star, c_star
      type(c_ptr), value, intent(in) :: x_star, traction, gap, message
      integer(c_int) :: status
      status = profile_core(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         message, message_capacity)
   end function compat_profile_msg

   !> 0.2 wa_gap_path_msg: wa_gap_path.
   function compat_gap_path_msg(model, alpha, mu, capacity, stage, event, zone_case, a_star, &
         c_star, p_star, gbar, n_events, w_star, w_fraction, g_touch, message, &
         message_capacity) result(status) bind(C, name="wa_gap_path_msg")
      integer(c_int), value, intent(in) :: model, capacity, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: stage, event, zone_case, a_star, c_star, p_star, &
         gbar, n_events, w_star, w_fraction, g_touch, message
      integer(c_int) :: status
      status = gap_path_core(model, alpha, mu, capacity, [stage, event, zone_case], &
         [a_star, c_star, p_star, gbar], n_events, [w_star, w_fraction, g_touch], message, &
         message_capacity)
   end function compat_gap_path_msg

   !> 0.2 wa_gap_law_msg: wa_gap_law.
   function compat_gap_law_msg(model, alpha, mu, n, gbar, p_approach, p_retract, &
         dpdg_approach, dpdg_retract, message, message_capacity) result(status) &
         bind(C, name="wa_gap_law_msg")
      integer(c_int), value, intent(in) :: model, n, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: gbar, p_approach, p_retract, dpdg_approach, &
         dpdg_retract, message
      integer(c_int) :: status
      status = gap_law_core(model, alpha, mu, n, gbar, [p_approach, p_retract, &
         dpdg_approach, dpdg_retract], message, message_capacity)
   end function compat_gap_law_msg

   !> 0.2 wa_gap_critical_msg: wa_gap_critical.
   function compat_gap_critical_msg(model, alpha, mu, values, message, message_capacity) &
         result(status) bind(C, name="wa_gap_critical_msg")
      integer(c_int), value, intent(in) :: model, message_capacity
      real(c_double), value, intent(in) :: alpha, mu
      type(c_ptr), value, intent(in) :: values, message
      integer(c_int) :: status
      status = gap_critical_core(model, alpha, mu, values, message, message_capacity)
   end function compat_gap_critical_msg

   !> 0.2 wa_adhesion_map_control: wa_adhesion_map with n_mu = 60, no message.
   function compat_adhesion_map_control(model, control, n_alpha, alpha, mu_lo, mu_hi, &
         capacity, boundary_code, alpha_out, mu_out, n_out) result(status) &
         bind(C, name="wa_adhesion_map_control")
      integer(c_int), value, intent(in) :: model, control, n_alpha, capacity
      type(c_ptr), value, intent(in) :: alpha, boundary_code, alpha_out, mu_out, n_out
      real(c_double), value, intent(in) :: mu_lo, mu_hi
      integer(c_int) :: status
      status = map_core(model, control, n_alpha, alpha, mu_lo, mu_hi, map_n_mu_02, capacity, &
         boundary_code, [alpha_out, mu_out], n_out, c_null_ptr, 0_c_int)
   end function compat_adhesion_map_control

end module wa_capi_compat
