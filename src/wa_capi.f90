!> The C interface (SPEC section 5): every `bind(C)` export of the library and nothing
!> else; the declarations are in include/wavyadhesion.h.
!>
!> Every function taking pointers returns an `int` status (0 = ok) and writes its results
!> through the pointers; arrays are caller-allocated with an explicit capacity; nothing
!> is allocated for the caller to free. NULL result pointers are reported as
!> wa_invalid_argument, never dereferenced. The `_msg` variants also copy a message that
!> names the failing argument and its valid range into a caller buffer.
!> Thread safe: no state survives a call (the status texts are immutable data).
module wa_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_char, &
      c_associated, c_f_pointer, c_loc, c_null_ptr
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
   use wa_status, only: wa_ok, wa_invalid_argument, wa_capacity_too_small, &
      wa_numerical_error, wa_no_solution, set_error
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_kernels, only: westergaard_load, jkr_load
   use wa_models, only: check_model, model_equilibrium, model_roots, model_profile
   use wa_branch, only: branch_type, trace_branch
   use wa_loadpath, only: path_type, load_path, critical_forces, critical_sweep
   use wa_release, only: wa_version
   use wa_map, only: map_type, adhesion_map, map_control_load
   use wa_gappath, only: gap_path_type, gap_path, gap_law
   use wa_gapcritical, only: gap_critical_type, gap_critical, gap_critical_values, &
      gap_critical_count
   implicit none
   private

   public :: capi_westergaard_load, capi_jkr_load, capi_equilibrium, capi_equilibrium_msg, &
      capi_roots, capi_roots_msg, capi_status_message
   public :: capi_trace_branch, capi_trace_branch_msg, capi_critical_forces, &
      capi_critical_forces_msg, capi_load_path, capi_load_path_msg, capi_critical_sweep, &
      capi_critical_sweep_msg, capi_critical_sweep_status
   public :: capi_version
   public :: capi_adhesion_map, capi_adhesion_map_control
   public :: capi_profile, capi_profile_msg, capi_equilibrium_gap, capi_equilibrium_gap_msg, &
      capi_roots_gap, capi_roots_gap_msg, capi_trace_branch_gap, capi_trace_branch_gap_msg
   public :: capi_gap_path, capi_gap_path_msg, capi_gap_law, capi_gap_law_msg, &
      capi_gap_critical, capi_gap_critical_msg

   !> Length of one status text, NUL included.
   integer, parameter :: text_len = 32
   !> Largest status code with a text of its own; others read "unknown status".
   integer, parameter :: last_status = wa_numerical_error
   !> Buffer for the library's messages before they are copied to C.
   integer, parameter :: msg_len = 256
   !> States held before asking for a larger buffer (more roots than this are rare).
   integer, parameter :: roots_buffer = 64

   !> NUL-terminated version text for wa_version(); immutable data like status_texts.
   character(kind=c_char, len=len(wa_version) + 1), target, save, protected :: &
      version_text = wa_version//c_null_char

   !> NUL-terminated status texts, same wording as wa_status::status_message, index =
   !> status code, last entry = unknown. Immutable data: nothing ever assigns to it (the
   !> only way to hand C a `const char *` without allocating). Not mutable state.
   character(kind=c_char, len=text_len), target, save, protected :: &
      status_texts(0:last_status + 1) = [character(kind=c_char, len=text_len) :: &
      "ok"//c_null_char, &
      "invalid argument"//c_null_char, &
      "no solution"//c_null_char, &
      "iteration did not converge"//c_null_char, &
      "output capacity too small"//c_null_char, &
      "numerical error"//c_null_char, &
      "unknown status"//c_null_char]

contains

   !> double wa_westergaard_load(double a_star): P* = sin^2(pi a*); NaN outside [0, 1/2].
   function capi_westergaard_load(a_star) result(p) bind(C, name="wa_westergaard_load")
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      real(c_double) :: p
      p = westergaard_load(a_star)
   end function capi_westergaard_load

   !> double wa_jkr_load(double alpha, double a_star): P* = sin^2(pi a*) - alpha
   !> sqrt(tan(pi a*)); -Infinity at a* = 1/2; NaN for alpha < 0 or a* outside [0, 1/2].
   function capi_jkr_load(alpha, a_star) result(p) bind(C, name="wa_jkr_load")
      !> Johnson's parameter, >= 0
      real(c_double), value, intent(in) :: alpha
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      real(c_double) :: p
      p = jkr_load(alpha, a_star)
   end function capi_jkr_load

   !> int wa_equilibrium(model, alpha, mu, a_star, *c_star, *P_star, *zone_case):
   !> the principal equilibrium. On failure *c_star = *P_star = NaN, *zone_case = 0.
   function capi_equilibrium(model, alpha, mu, a_star, c_star, p_star, zone_case) &
         result(status) bind(C, name="wa_equilibrium")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *: receives c*
      type(c_ptr), value, intent(in) :: c_star
      !> double *: receives P*
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the zone case (1, 2 or 3)
      type(c_ptr), value, intent(in) :: zone_case
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, status, msg)
   end function capi_equilibrium

   !> int wa_equilibrium_msg(..., char *message, int message_capacity): as
   !> wa_equilibrium, and copies the reason for a failure ("" on success), truncated and
   !> NUL-terminated, to `message` when it is not NULL and message_capacity > 0.
   function capi_equilibrium_msg(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         message, message_capacity) result(status) bind(C, name="wa_equilibrium_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *: receives c*
      type(c_ptr), value, intent(in) :: c_star
      !> double *: receives P*
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the zone case (1, 2 or 3)
      type(c_ptr), value, intent(in) :: zone_case
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_equilibrium_msg

   !> int wa_roots(model, alpha, mu, a_star, capacity, c_star[], P_star[], zone_case[],
   !> *n_roots): every equilibrium at a*. *n_roots is the total; when it exceeds
   !> `capacity`, the first `capacity` states are written and the status is
   !> WA_CAPACITY_TOO_SMALL. On any other failure *n_roots = 0.
   function capi_roots(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots) result(status) bind(C, name="wa_roots")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the three arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives c* of each state
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each state
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each state
      type(c_ptr), value, intent(in) :: zone_case
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg)
   end function capi_roots

   !> int wa_roots_msg(..., char *message, int message_capacity): as wa_roots, with the
   !> message of wa_equilibrium_msg.
   function capi_roots_msg(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, message, message_capacity) result(status) bind(C, name="wa_roots_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the three arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives c* of each state
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each state
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each state
      type(c_ptr), value, intent(in) :: zone_case
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_roots_msg

   !> int wa_trace_branch(model, alpha, mu, capacity, a_star[], c_star[], P_star[],
   !> zone_case[], stable[], event[], *n_points): the equilibrium branch by continuation
   !> (trace_branch), in the order of the curve. *n_points is the number of points; when
   !> it exceeds `capacity` the first `capacity` points are written and the status is
   !> WA_CAPACITY_TOO_SMALL. On any other failure *n_points = 0.
   function capi_trace_branch(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, n_points) result(status) bind(C, name="wa_trace_branch")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the six arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives a* of each point
      type(c_ptr), value, intent(in) :: a_star
      !> double[capacity]: receives c* of each point
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each point
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each point
      type(c_ptr), value, intent(in) :: zone_case
      !> int[capacity]: receives 1 where dP*/da* > 0 (stable under load control), else 0
      type(c_ptr), value, intent(in) :: stable
      !> int[capacity]: receives the event code of each point (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: event
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_points
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star], &
         [zone_case, stable, event], n_points, status, msg)
   end function capi_trace_branch

   !> int wa_trace_branch_msg(..., char *message, int message_capacity): as
   !> wa_trace_branch, with the message of wa_equilibrium_msg.
   function capi_trace_branch_msg(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, n_points, message, message_capacity) result(status) &
         bind(C, name="wa_trace_branch_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the six arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives a* of each point
      type(c_ptr), value, intent(in) :: a_star
      !> double[capacity]: receives c* of each point
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each point
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each point
      type(c_ptr), value, intent(in) :: zone_case
      !> int[capacity]: receives 1 where dP*/da* > 0 (stable under load control), else 0
      type(c_ptr), value, intent(in) :: stable
      !> int[capacity]: receives the event code of each point (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: event
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_points
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star], &
         [zone_case, stable, event], n_points, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_trace_branch_msg

   !> int wa_critical_forces(model, alpha, mu, *P_fc, *P_pf): the load at which full
   !> contact is first reached on loading from P* = 0 and the pull-off load on unloading
   !> from full contact (JKR: -Infinity). On failure *P_fc = *P_pf = NaN.
   function capi_critical_forces(model, alpha, mu, p_fc, p_pf) result(status) &
         bind(C, name="wa_critical_forces")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> double *: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double *: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call critical_core(model, alpha, mu, p_fc, p_pf, status, msg)
   end function capi_critical_forces

   !> int wa_critical_forces_msg(..., char *message, int message_capacity): as
   !> wa_critical_forces, with the message of wa_equilibrium_msg.
   function capi_critical_forces_msg(model, alpha, mu, p_fc, p_pf, message, &
         message_capacity) result(status) bind(C, name="wa_critical_forces_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> double *: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double *: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call critical_core(model, alpha, mu, p_fc, p_pf, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_critical_forces_msg

   !> int wa_load_path(model, alpha, mu, capacity, stage[], event[], a_star[], c_star[],
   !> P_star[], *n_events, *P_fc, *P_pf): the events of load-controlled loading (stage 1)
   !> and unloading (stage 2), with P_fc* and P_pf*. *n_events is the number of events;
   !> when it exceeds `capacity` the first `capacity` are written (P_fc, P_pf too) and
   !> the status is WA_CAPACITY_TOO_SMALL. On any other failure *n_events = 0 and
   !> *P_fc = *P_pf = NaN.
   function capi_load_path(model, alpha, mu, capacity, stage, event, a_star, c_star, &
         p_star, n_events, p_fc, p_pf) result(status) bind(C, name="wa_load_path")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the five arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: receives the stage of each event (WA_STAGE_*)
      type(c_ptr), value, intent(in) :: stage
      !> int[capacity]: receives the event code (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: event
      !> double[capacity]: receives a* of each event
      type(c_ptr), value, intent(in) :: a_star
      !> double[capacity]: receives c* of each event
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each event
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the number of events
      type(c_ptr), value, intent(in) :: n_events
      !> double *: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double *: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call path_core(model, alpha, mu, capacity, [stage, event], [a_star, c_star, p_star], &
         n_events, p_fc, p_pf, status, msg)
   end function capi_load_path

   !> int wa_load_path_msg(..., char *message, int message_capacity): as wa_load_path,
   !> with the message of wa_equilibrium_msg.
   function capi_load_path_msg(model, alpha, mu, capacity, stage, event, a_star, c_star, &
         p_star, n_events, p_fc, p_pf, message, message_capacity) result(status) &
         bind(C, name="wa_load_path_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the five arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: receives the stage of each event (WA_STAGE_*)
      type(c_ptr), value, intent(in) :: stage
      !> int[capacity]: receives the event code (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: event
      !> double[capacity]: receives a* of each event
      type(c_ptr), value, intent(in) :: a_star
      !> double[capacity]: receives c* of each event
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each event
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the number of events
      type(c_ptr), value, intent(in) :: n_events
      !> double *: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double *: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call path_core(model, alpha, mu, capacity, [stage, event], [a_star, c_star, p_star], &
         n_events, p_fc, p_pf, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_load_path_msg

   !> int wa_critical_sweep(model, alpha, n_mu, mu[], P_fc[], P_pf[], fc_mechanism[],
   !> pf_mechanism[]): P_fc*, P_pf* and how each is reached (WA_MECHANISM_*) for one
   !> alpha over n_mu values of mu. Every argument (every mu) is validated before any
   !> work; an invalid one writes NaN (mechanisms -1) everywhere. A mu whose load path
   !> fails gets NaN (-1) in its row only; every other row is written and the status of
   !> the first failing row is returned (wa_critical_sweep_status gives each row's).
   function capi_critical_sweep(model, alpha, n_mu, mu, p_fc, p_pf, fc_mechanism, &
         pf_mechanism) result(status) bind(C, name="wa_critical_sweep")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Number of mu values, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n_mu
      !> const double[n_mu]: transition parameters, each >= 0
      type(c_ptr), value, intent(in) :: mu
      !> double[n_mu]: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double[n_mu]: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      !> int[n_mu]: receives how full contact is reached
      type(c_ptr), value, intent(in) :: fc_mechanism
      !> int[n_mu]: receives how contact is lost
      type(c_ptr), value, intent(in) :: pf_mechanism
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call sweep_core(model, alpha, n_mu, mu, [p_fc, p_pf], [fc_mechanism, pf_mechanism], &
         c_null_ptr, .false., status, msg)
   end function capi_critical_sweep

   !> int wa_critical_sweep_msg(..., char *message, int message_capacity): as
   !> wa_critical_sweep, with the message of wa_equilibrium_msg.
   function capi_critical_sweep_msg(model, alpha, n_mu, mu, p_fc, p_pf, fc_mechanism, &
         pf_mechanism, message, message_capacity) result(status) &
         bind(C, name="wa_critical_sweep_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Number of mu values, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n_mu
      !> const double[n_mu]: transition parameters, each >= 0
      type(c_ptr), value, intent(in) :: mu
      !> double[n_mu]: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double[n_mu]: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      !> int[n_mu]: receives how full contact is reached
      type(c_ptr), value, intent(in) :: fc_mechanism
      !> int[n_mu]: receives how contact is lost
      type(c_ptr), value, intent(in) :: pf_mechanism
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call sweep_core(model, alpha, n_mu, mu, [p_fc, p_pf], [fc_mechanism, pf_mechanism], &
         c_null_ptr, .false., status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_critical_sweep_msg

   !> int wa_critical_sweep_status(..., int *row_status, char *message,
   !> int message_capacity): as wa_critical_sweep_msg, and row_status[i] receives the
   !> status of row i (WA_OK where its forces were computed; on an invalid argument,
   !> that status in every row).
   function capi_critical_sweep_status(model, alpha, n_mu, mu, p_fc, p_pf, fc_mechanism, &
         pf_mechanism, row_status, message, message_capacity) result(status) &
         bind(C, name="wa_critical_sweep_status")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Number of mu values, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n_mu
      !> const double[n_mu]: transition parameters, each >= 0
      type(c_ptr), value, intent(in) :: mu
      !> double[n_mu]: receives P_fc*
      type(c_ptr), value, intent(in) :: p_fc
      !> double[n_mu]: receives P_pf*
      type(c_ptr), value, intent(in) :: p_pf
      !> int[n_mu]: receives how full contact is reached
      type(c_ptr), value, intent(in) :: fc_mechanism
      !> int[n_mu]: receives how contact is lost
      type(c_ptr), value, intent(in) :: pf_mechanism
      !> int[n_mu]: receives the status of each row
      type(c_ptr), value, intent(in) :: row_status
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call sweep_core(model, alpha, n_mu, mu, [p_fc, p_pf], [fc_mechanism, pf_mechanism], &
         row_status, .true., status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_critical_sweep_status

   !> int wa_profile(model, alpha, mu, a_star, c_star, n, x_star[], traction[], gap[]):
   !> the traction p/p* and the gap h/Delta at n points x* of the state at a* identified
   !> by c* (wa_models::model_state: the root at a* with the nearest c*, within 1e-6; MD
   !> at a* = 0: the no-contact state with zone half-width c* < 1/2). On any failure,
   !> when n > 0, every element of traction and gap (each not NULL) is NaN.
   function capi_profile(model, alpha, mu, a_star, c_star, n, x_star, traction, gap) &
         result(status) bind(C, name="wa_profile")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Interaction-zone half-width of the state, in [0, 1/2]
      real(c_double), value, intent(in) :: c_star
      !> Number of points, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n
      !> const double[n]: the points x* (any finite values; period 1, crest at 0)
      type(c_ptr), value, intent(in) :: x_star
      !> double[n]: receives p/p* (positive = compressive)
      type(c_ptr), value, intent(in) :: traction
      !> double[n]: receives h/Delta (>= 0, 0 on the contact)
      type(c_ptr), value, intent(in) :: gap
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call profile_core(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, status, &
         msg)
   end function capi_profile

   !> int wa_profile_msg(..., char *message, int message_capacity): as wa_profile, with
   !> the message of wa_equilibrium_msg.
   function capi_profile_msg(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         message, message_capacity) result(status) bind(C, name="wa_profile_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Interaction-zone half-width of the state, in [0, 1/2]
      real(c_double), value, intent(in) :: c_star
      !> Number of points, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n
      !> const double[n]: the points x* (any finite values; period 1, crest at 0)
      type(c_ptr), value, intent(in) :: x_star
      !> double[n]: receives p/p* (positive = compressive)
      type(c_ptr), value, intent(in) :: traction
      !> double[n]: receives h/Delta (>= 0, 0 on the contact)
      type(c_ptr), value, intent(in) :: gap
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call profile_core(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, status, &
         msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_profile_msg

   !> int wa_equilibrium_gap(model, alpha, mu, a_star, *c_star, *P_star, *zone_case,
   !> *gbar): as wa_equilibrium, and the mean gap gbar* = gbar/Delta of the state. On
   !> failure *c_star = *P_star = *gbar = NaN, *zone_case = 0.
   function capi_equilibrium_gap(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar) &
         result(status) bind(C, name="wa_equilibrium_gap")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *: receives c*
      type(c_ptr), value, intent(in) :: c_star
      !> double *: receives P*
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the zone case (1, 2 or 3)
      type(c_ptr), value, intent(in) :: zone_case
      !> double *: receives gbar*
      type(c_ptr), value, intent(in) :: gbar
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, status, msg, &
         gbar)
   end function capi_equilibrium_gap

   !> int wa_equilibrium_gap_msg(..., char *message, int message_capacity): as
   !> wa_equilibrium_gap, with the message of wa_equilibrium_msg.
   function capi_equilibrium_gap_msg(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         gbar, message, message_capacity) result(status) bind(C, name="wa_equilibrium_gap_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *: receives c*
      type(c_ptr), value, intent(in) :: c_star
      !> double *: receives P*
      type(c_ptr), value, intent(in) :: p_star
      !> int *: receives the zone case (1, 2 or 3)
      type(c_ptr), value, intent(in) :: zone_case
      !> double *: receives gbar*
      type(c_ptr), value, intent(in) :: gbar
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, status, msg, &
         gbar)
      call copy_message(status, msg, message, message_capacity)
   end function capi_equilibrium_gap_msg

   !> int wa_roots_gap(model, alpha, mu, a_star, capacity, c_star[], P_star[],
   !> zone_case[], gbar[], *n_roots): as wa_roots, and the mean gap of each state.
   function capi_roots_gap(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         gbar, n_roots) result(status) bind(C, name="wa_roots_gap")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the four arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives c* of each state
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each state
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each state
      type(c_ptr), value, intent(in) :: zone_case
      !> double[capacity]: receives gbar* of each state
      type(c_ptr), value, intent(in) :: gbar
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg, gbar)
   end function capi_roots_gap

   !> int wa_roots_gap_msg(..., char *message, int message_capacity): as wa_roots_gap,
   !> with the message of wa_equilibrium_msg.
   function capi_roots_gap_msg(model, alpha, mu, a_star, capacity, c_star, p_star, &
         zone_case, gbar, n_roots, message, message_capacity) result(status) &
         bind(C, name="wa_roots_gap_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the four arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives c* of each state
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each state
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each state
      type(c_ptr), value, intent(in) :: zone_case
      !> double[capacity]: receives gbar* of each state
      type(c_ptr), value, intent(in) :: gbar
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg, gbar)
      call copy_message(status, msg, message, message_capacity)
   end function capi_roots_gap_msg

   !> int wa_trace_branch_gap(model, alpha, mu, capacity, a_star[], c_star[], P_star[],
   !> zone_case[], stable[], event[], gbar[], *n_points): as wa_trace_branch, and the
   !> mean gap of each point.
   function capi_trace_branch_gap(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, gbar, n_points) result(status) &
         bind(C, name="wa_trace_branch_gap")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the seven arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives a* of each point
      type(c_ptr), value, intent(in) :: a_star
      !> double[capacity]: receives c* of each point
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each point
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each point
      type(c_ptr), value, intent(in) :: zone_case
      !> int[capacity]: receives 1 where stable under load control, else 0
      type(c_ptr), value, intent(in) :: stable
      !> int[capacity]: receives the event code of each point (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: event
      !> double[capacity]: receives gbar* of each point
      type(c_ptr), value, intent(in) :: gbar
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_points
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star, gbar], &
         [zone_case, stable, event], n_points, status, msg)
   end function capi_trace_branch_gap

   !> int wa_trace_branch_gap_msg(..., char *message, int message_capacity): as
   !> wa_trace_branch_gap, with the message of wa_equilibrium_msg.
   function capi_trace_branch_gap_msg(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, gbar, n_points, message, message_capacity) &
         result(status) bind(C, name="wa_trace_branch_gap_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the seven arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: receives a* of each point
      type(c_ptr), value, intent(in) :: a_star
      !> double[capacity]: receives c* of each point
      type(c_ptr), value, intent(in) :: c_star
      !> double[capacity]: receives P* of each point
      type(c_ptr), value, intent(in) :: p_star
      !> int[capacity]: receives the zone case of each point
      type(c_ptr), value, intent(in) :: zone_case
      !> int[capacity]: receives 1 where stable under load control, else 0
      type(c_ptr), value, intent(in) :: stable
      !> int[capacity]: receives the event code of each point (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: event
      !> double[capacity]: receives gbar* of each point
      type(c_ptr), value, intent(in) :: gbar
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_points
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star, gbar], &
         [zone_case, stable, event], n_points, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_trace_branch_gap_msg

   !> const char *wa_status_message(int status): a static NUL-terminated text, never
   !> NULL ("unknown status" for codes the library does not return).
   function capi_status_message(status) result(text) bind(C, name="wa_status_message")
      !> A status code returned by the library
      integer(c_int), value, intent(in) :: status
      type(c_ptr) :: text
      if (status >= 0 .and. status <= last_status) then
         text = c_loc(status_texts(status))
      else
         text = c_loc(status_texts(last_status + 1))
      end if
   end function capi_status_message


   !> const char *wa_version(void): the library's version, e.g. "0.2.0": a static
   !> NUL-terminated text, never NULL.
   function capi_version() result(text) bind(C, name="wa_version")
      type(c_ptr) :: text
      text = c_loc(version_text)
   end function capi_version

   ! ---------------------------------------------------------------- internals

   !> Validate, solve, write the principal state (NaN, NaN, 0 on failure); with gbar
   !> (wa_equilibrium_gap) also its mean gap (NaN on failure).
   subroutine equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, &
         status, msg, gbar)
      integer(c_int), intent(in) :: model
      real(c_double), intent(in) :: alpha, mu, a_star
      type(c_ptr), intent(in) :: c_star, p_star, zone_case
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      type(c_ptr), intent(in), optional :: gbar
      real(c_double), pointer :: c_out, p_out, g_out
      integer(c_int), pointer :: z_out
      type(params_type) :: params
      type(state_type) :: state
      integer :: stat

      msg = ""
      call put_nan(c_star)
      call put_nan(p_star)
      call put_int(zone_case, 0)
      if (present(gbar)) call put_nan(gbar)
      if (.not. (c_associated(c_star) .and. c_associated(p_star) .and. &
            c_associated(zone_case))) then
         call set_error(wa_invalid_argument, "c_star, P_star and zone_case must not be NULL", &
            stat, msg)
         status = int(stat, c_int)
         return
      end if
      if (present(gbar)) then
         if (.not. c_associated(gbar)) then
            call set_error(wa_invalid_argument, "gbar must not be NULL", stat, msg)
            status = int(stat, c_int)
            return
         end if
      end if
      call c_f_pointer(c_star, c_out)
      call c_f_pointer(p_star, p_out)
      call c_f_pointer(zone_case, z_out)
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call model_equilibrium(int(model), params, a_star, state, stat, msg)
      if (stat == wa_ok .and. present(gbar)) then
         call check_gbar([state], stat, msg)
         if (stat == wa_ok) then
            call c_f_pointer(gbar, g_out)
            g_out = state%gbar
         end if
      end if
      if (stat == wa_ok) then
         c_out = state%c_star
         p_out = state%p_star
         z_out = int(state%zone_case, c_int)
      end if
      status = int(stat, c_int)
   end subroutine equilibrium_core

   !> Validate, solve, write min(n, capacity) states and n (0 on failures other than
   !> a too small capacity); with gbar (wa_roots_gap) also their mean gaps.
   subroutine roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         n_roots, status, msg, gbar)
      integer(c_int), intent(in) :: model, capacity
      real(c_double), intent(in) :: alpha, mu, a_star
      type(c_ptr), intent(in) :: c_star, p_star, zone_case, n_roots
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      type(c_ptr), intent(in), optional :: gbar
      integer(c_int), pointer :: n_out
      type(params_type) :: params
      type(state_type), allocatable :: states(:)
      integer :: stat, n

      msg = ""
      call put_int(n_roots, 0)
      call check_roots_pointers(capacity, c_star, p_star, zone_case, n_roots, stat, msg)
      if (stat == wa_ok .and. present(gbar)) then
         if (capacity > 0 .and. .not. c_associated(gbar)) call set_error( &
            wa_invalid_argument, "gbar must not be NULL when capacity > 0", stat, msg)
      end if
      if (stat /= wa_ok) then
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(n_roots, n_out)
      n = 0
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) then
         allocate (states(min(int(capacity), roots_buffer)))
         call model_roots(int(model), params, a_star, states, n, stat, msg)
         if (stat == wa_capacity_too_small .and. size(states) < min(n, int(capacity))) then
            ! our buffer was shorter than the caller's: solve again with room for
            ! min(n, capacity) states (the count does not change: the solve is deterministic)
            deallocate (states)
            allocate (states(min(n, int(capacity))))
            msg = ""
            call model_roots(int(model), params, a_star, states, n, stat, msg)
         end if
      end if
      if (present(gbar) .and. (stat == wa_ok .or. stat == wa_capacity_too_small)) then
         call check_gbar(states(1:min(n, size(states))), stat, msg)
         if (stat /= wa_ok .and. stat /= wa_capacity_too_small) n = 0
      end if
      if (stat == wa_ok .or. stat == wa_capacity_too_small) then
         call store_states(states(1:min(n, size(states))), c_star, p_star, zone_case)
         if (present(gbar)) call store_reals(gbar, states(1:min(n, size(states)))%gbar)
         n_out = int(n, c_int)
      end if
      status = int(stat, c_int)
   end subroutine roots_core

   !> n_roots must not be NULL; the arrays not NULL unless capacity is 0; capacity >= 0.
   subroutine check_roots_pointers(capacity, c_star, p_star, zone_case, n_roots, stat, msg)
      integer(c_int), intent(in) :: capacity
      type(c_ptr), intent(in) :: c_star, p_star, zone_case, n_roots
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=12) :: text

      stat = wa_ok
      if (.not. c_associated(n_roots)) then
         call set_error(wa_invalid_argument, "n_roots must not be NULL", stat, msg)
      else if (capacity < 0) then
         write (text, '(i0)') capacity
         call set_error(wa_invalid_argument, "capacity = "//trim(text)// &
            " is outside its valid range [0, inf)", stat, msg)
      else if (capacity > 0 .and. .not. (c_associated(c_star) .and. c_associated(p_star) &
            .and. c_associated(zone_case))) then
         call set_error(wa_invalid_argument, &
            "c_star, P_star and zone_case must not be NULL when capacity > 0", stat, msg)
      end if
   end subroutine check_roots_pointers

   !> Copy states into the caller's three arrays (nothing when there are none).
   subroutine store_states(states, c_star, p_star, zone_case)
      type(state_type), intent(in) :: states(:)
      type(c_ptr), intent(in) :: c_star, p_star, zone_case
      real(c_double), pointer :: c_out(:), p_out(:)
      integer(c_int), pointer :: z_out(:)
      integer :: k

      if (size(states) == 0) return
      call c_f_pointer(c_star, c_out, [size(states)])
      call c_f_pointer(p_star, p_out, [size(states)])
      call c_f_pointer(zone_case, z_out, [size(states)])
      do k = 1, size(states)
         c_out(k) = states(k)%c_star
         p_out(k) = states(k)%p_star
         z_out(k) = int(states(k)%zone_case, c_int)
      end do
   end subroutine store_states

   !> Validate, trace, write min(n, capacity) points and n (0 on failures other than a
   !> too small capacity). reals = [a_star, c_star, P_star] (wa_trace_branch_gap: and
   !> gbar), ints = [zone_case, stable, event].
   subroutine branch_core(model, alpha, mu, capacity, reals, ints, n_points, status, msg)
      integer(c_int), intent(in) :: model, capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: reals(:), ints(3), n_points
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      integer(c_int), pointer :: n_out
      type(params_type) :: params
      type(branch_type) :: branch
      integer :: stat, m

      msg = ""
      call put_int(n_points, 0)
      if (size(reals) == 4) then
         call check_outputs("n_points", n_points, "capacity", capacity, [reals, ints], &
            "a_star, c_star, P_star, zone_case, stable, event and gbar", stat, msg)
      else
         call check_outputs("n_points", n_points, "capacity", capacity, [reals, ints], &
            "a_star, c_star, P_star, zone_case, stable and event", stat, msg)
      end if
      if (stat /= wa_ok) then
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(n_points, n_out)
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call trace_branch(int(model), params, branch, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok .and. size(reals) == 4) call check_gbar_values(branch%gbar(1:branch%n), &
         stat, msg)
      if (stat == wa_ok) then
         m = min(branch%n, int(capacity))
         if (size(reals) == 4) call store_reals(reals(4), branch%gbar(1:m))
         call store_reals(reals(1), branch%a_star(1:m))
         call store_reals(reals(2), branch%c_star(1:m))
         call store_reals(reals(3), branch%p_star(1:m))
         call store_ints(ints(1), branch%zone_case(1:m))
         call store_ints(ints(2), merge(1, 0, branch%stable(1:m)))
         call store_ints(ints(3), branch%event(1:m))
         n_out = int(branch%n, c_int)
         if (branch%n > capacity) call too_small("the branch has", "points", branch%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
   end subroutine branch_core

   !> Validate, compute P_fc* and P_pf* (NaN on failure).
   subroutine critical_core(model, alpha, mu, p_fc, p_pf, status, msg)
      integer(c_int), intent(in) :: model
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: p_fc, p_pf
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      real(c_double), pointer :: fc_out, pf_out
      type(params_type) :: params
      real(c_double) :: fc, pf
      integer :: stat

      msg = ""
      call put_nan(p_fc)
      call put_nan(p_pf)
      if (.not. (c_associated(p_fc) .and. c_associated(p_pf))) then
         call set_error(wa_invalid_argument, "P_fc and P_pf must not be NULL", stat, msg)
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(p_fc, fc_out)
      call c_f_pointer(p_pf, pf_out)
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call critical_forces(int(model), params, fc, pf, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         fc_out = fc
         pf_out = pf
      end if
      status = int(stat, c_int)
   end subroutine critical_core

   !> Validate, follow the load path, write min(n, capacity) events, n, P_fc*, P_pf*.
   !> ints = [stage, event], reals = [a_star, c_star, P_star].
   subroutine path_core(model, alpha, mu, capacity, ints, reals, n_events, p_fc, p_pf, &
         status, msg)
      integer(c_int), intent(in) :: model, capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: ints(2), reals(3), n_events, p_fc, p_pf
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      integer(c_int), pointer :: n_out
      real(c_double), pointer :: fc_out, pf_out
      type(params_type) :: params
      type(path_type) :: path
      integer :: stat, m

      msg = ""
      call put_int(n_events, 0)
      call put_nan(p_fc)
      call put_nan(p_pf)
      call check_outputs("n_events", n_events, "capacity", capacity, [ints, reals], &
         "stage, event, a_star, c_star and P_star", stat, msg)
      if (stat == wa_ok .and. .not. (c_associated(p_fc) .and. c_associated(p_pf))) &
         call set_error(wa_invalid_argument, "P_fc and P_pf must not be NULL", stat, msg)
      if (stat /= wa_ok) then
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(n_events, n_out)
      call c_f_pointer(p_fc, fc_out)
      call c_f_pointer(p_pf, pf_out)
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call load_path(int(model), params, path, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         m = min(path%n, int(capacity))
         call store_ints(ints(1), path%stage(1:m))
         call store_ints(ints(2), path%event(1:m))
         call store_reals(reals(1), path%a_star(1:m))
         call store_reals(reals(2), path%c_star(1:m))
         call store_reals(reals(3), path%p_star(1:m))
         n_out = int(path%n, c_int)
         fc_out = path%p_fc
         pf_out = path%p_pf
         if (path%n > capacity) call too_small("the load path has", "events", path%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
   end subroutine path_core

   !> Validate everything (every mu first), then sweep: a failing mu leaves NaN and -1 in
   !> its row only (an invalid argument: in every row). reals = [P_fc, P_pf],
   !> ints = [fc_mechanism, pf_mechanism]; rows = row_status, required when want_rows.
   subroutine sweep_core(model, alpha, n_mu, mu, reals, ints, rows, want_rows, status, msg)
      integer(c_int), intent(in) :: model, n_mu
      real(c_double), intent(in) :: alpha
      type(c_ptr), intent(in) :: mu, reals(2), ints(2), rows
      logical, intent(in) :: want_rows
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      real(c_double), pointer :: mu_in(:), fc_out(:), pf_out(:)
      integer(c_int), pointer :: fcm_out(:), pfm_out(:), rows_out(:)
      real(c_double), allocatable :: p_fc(:), p_pf(:)
      integer, allocatable :: fc_mech(:), pf_mech(:), row_stat(:)
      type(params_type) :: params
      integer :: stat, i
      character(len=12) :: text

      msg = ""
      if (n_mu > 0) then                      ! the failure values, in every non-NULL array
         call put_nans(reals(1), n_mu)
         call put_nans(reals(2), n_mu)
         call put_ints(ints(1), n_mu, -1)
         call put_ints(ints(2), n_mu, -1)
      end if
      if (want_rows) then
         call check_outputs("", mu, "n_mu", n_mu, [mu, reals, ints, rows], &
            "mu, P_fc, P_pf, fc_mechanism, pf_mechanism and row_status", stat, msg)
      else
         call check_outputs("", mu, "n_mu", n_mu, [mu, reals, ints], &
            "mu, P_fc, P_pf, fc_mechanism and pf_mechanism", stat, msg)
      end if
      if (stat /= wa_ok) then
         if (want_rows .and. n_mu > 0) call put_ints(rows, n_mu, stat)
         status = int(stat, c_int)
         return
      end if
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, 0.0_c_double, params, stat, msg)
      if (n_mu == 0) then                     ! nothing to compute; model and alpha checked
         status = int(stat, c_int)
         return
      end if
      call c_f_pointer(mu, mu_in, [n_mu])
      call c_f_pointer(reals(1), fc_out, [n_mu])
      call c_f_pointer(reals(2), pf_out, [n_mu])
      call c_f_pointer(ints(1), fcm_out, [n_mu])
      call c_f_pointer(ints(2), pfm_out, [n_mu])
      do i = 1, int(n_mu)
         if (stat /= wa_ok) exit
         call new_params(alpha, mu_in(i), params, stat, msg)
         if (stat /= wa_ok) then
            write (text, '(i0)') i - 1
            msg = trim(msg)//" (mu["//trim(text)//"])"
         end if
      end do
      allocate (row_stat(n_mu))
      row_stat = stat
      if (stat == wa_ok) then
         allocate (p_fc(n_mu), p_pf(n_mu), fc_mech(n_mu), pf_mech(n_mu))
         call critical_sweep(int(model), alpha, mu_in, p_fc, p_pf, fc_mech, pf_mech, stat, &
            msg, row_stat)
         call internal_capacity(stat, msg)
         where (row_stat == wa_capacity_too_small) row_stat = wa_numerical_error
         fc_out = p_fc                        ! every row: NaN and -1 where one failed
         pf_out = p_pf
         fcm_out = int(fc_mech, c_int)
         pfm_out = int(pf_mech, c_int)
      end if
      if (want_rows) then
         call c_f_pointer(rows, rows_out, [n_mu])
         rows_out = int(row_stat, c_int)
      end if
      status = int(stat, c_int)
   end subroutine sweep_core

   !> wa_ok when every state's mean gap is a number >= 0, else wa_no_solution (never a
   !> NaN or the "not computed" -1 with an OK status).
   subroutine check_gbar(states, stat, msg)
      type(state_type), intent(in) :: states(:)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: msg
      call check_gbar_values(states%gbar, stat, msg)
   end subroutine check_gbar

   !> As check_gbar, for the values.
   subroutine check_gbar_values(gbar, stat, msg)
      real(c_double), intent(in) :: gbar(:)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: msg
      integer :: k
      do k = 1, size(gbar)
         if (.not. (gbar(k) >= 0.0_c_double .and. gbar(k) <= huge(gbar(k)))) then
            call set_error(wa_no_solution, "gbar: the mean gap of a state is not defined "// &
               "(not a finite number >= 0)", stat, msg)
            return
         end if
      end do
   end subroutine check_gbar_values

   !> Validate, identify the state (model_state), write its profile at n points (every
   !> element of traction and gap NaN on any failure, when n > 0 and they are not NULL).
   subroutine profile_core(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         status, msg)
      integer(c_int), intent(in) :: model, n
      real(c_double), intent(in) :: alpha, mu, a_star, c_star
      type(c_ptr), intent(in) :: x_star, traction, gap
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      real(c_double), pointer :: x_in(:), t_out(:), g_out(:)
      real(c_double), allocatable :: t(:), g(:)
      type(params_type) :: params
      type(state_type) :: state
      integer :: stat, k
      character(len=12) :: text

      msg = ""
      if (n > 0) then
         call put_nans(traction, n)
         call put_nans(gap, n)
      end if
      call check_outputs("", x_star, "n", n, [x_star, traction, gap], &
         "x_star, traction and gap", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok .and. n > 0) then         ! every argument before any work
         call c_f_pointer(x_star, x_in, [n])
         do k = 1, int(n)
            if (.not. ieee_is_finite(x_in(k))) then
               write (text, '(i0)') k - 1
               call set_error(wa_invalid_argument, "x_star["//trim(text)//"]: not a "// &
                  "finite number (any finite x* is valid: the period is 1)", stat, msg)
               exit
            end if
         end do
      end if
      if (stat == wa_ok) then
         allocate (t(max(0, n)), g(max(0, n)))
         if (n > 0) then
            call model_profile(int(model), params, a_star, x_in, t, g, state, stat, msg, &
               c_star)
         else
            call model_profile(int(model), params, a_star, [real(c_double) ::], t, g, state, &
               stat, msg, c_star)
         end if
         if (stat == wa_ok .and. n > 0) then
            call c_f_pointer(traction, t_out, [n])
            call c_f_pointer(gap, g_out, [n])
            t_out = t
            g_out = g
         end if
      end if
      status = int(stat, c_int)
   end subroutine profile_core

   !> The count pointer must not be NULL (when count_name is not empty); the size >= 0;
   !> the arrays not NULL unless the size is 0.
   subroutine check_outputs(count_name, count_ptr, size_name, capacity, arrays, array_names, &
         stat, msg)
      !> Name of the count pointer ("" when there is none)
      character(len=*), intent(in) :: count_name
      type(c_ptr), intent(in) :: count_ptr
      !> Name of the size argument ("capacity", "n_mu")
      character(len=*), intent(in) :: size_name
      integer(c_int), intent(in) :: capacity
      type(c_ptr), intent(in) :: arrays(:)
      !> Names of the arrays, for the message
      character(len=*), intent(in) :: array_names
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=12) :: text
      integer :: k

      stat = wa_ok
      if (len(count_name) > 0) then
         if (.not. c_associated(count_ptr)) then
            call set_error(wa_invalid_argument, count_name//" must not be NULL", stat, msg)
            return
         end if
      end if
      if (capacity < 0) then
         write (text, '(i0)') capacity
         call set_error(wa_invalid_argument, size_name//" = "//trim(text)// &
            " is outside its valid range [0, inf)", stat, msg)
         return
      end if
      if (capacity == 0) return
      do k = 1, size(arrays)
         if (.not. c_associated(arrays(k))) then
            call set_error(wa_invalid_argument, array_names//" must not be NULL when "// &
               size_name//" > 0", stat, msg)
            return
         end if
      end do
   end subroutine check_outputs

   !> WA_CAPACITY_TOO_SMALL with a message giving both sizes.
   subroutine too_small(what, items, n, capacity, stat, msg)
      character(len=*), intent(in) :: what, items
      integer, intent(in) :: n
      integer(c_int), intent(in) :: capacity
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=12) :: t_n, t_cap
      write (t_n, '(i0)') n
      write (t_cap, '(i0)') capacity
      call set_error(wa_capacity_too_small, "capacity = "//trim(t_cap)//" is too small: "// &
         what//" "//trim(t_n)//" "//items//" (the first "//trim(t_cap)//" were written)", &
         stat, msg)
   end subroutine too_small

   !> A wa_capacity_too_small from the numerics below a function whose only capacity is
   !> the caller's (checked here) is an internal buffer running short: report it as
   !> wa_numerical_error, so the caller never reads it as "your array is too small".
   subroutine internal_capacity(stat, msg)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: msg
      if (stat /= wa_capacity_too_small) return
      stat = wa_numerical_error
      msg = "internal buffer too small: "//msg
   end subroutine internal_capacity

   !> *ptr = NaN unless ptr is NULL (a failure's value, written before any check).
   subroutine put_nan(ptr)
      type(c_ptr), intent(in) :: ptr
      real(c_double), pointer :: out
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out)
      out = ieee_value(out, ieee_quiet_nan)
   end subroutine put_nan

   !> *ptr = value unless ptr is NULL.
   subroutine put_int(ptr, value)
      type(c_ptr), intent(in) :: ptr
      integer, intent(in) :: value
      integer(c_int), pointer :: out
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out)
      out = int(value, c_int)
   end subroutine put_int

   !> ptr[0..n-1] = NaN unless ptr is NULL (n > 0).
   subroutine put_nans(ptr, n)
      type(c_ptr), intent(in) :: ptr
      integer(c_int), intent(in) :: n
      real(c_double), pointer :: out(:)
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out, [n])
      out = ieee_value(1.0_c_double, ieee_quiet_nan)
   end subroutine put_nans

   !> ptr[0..n-1] = value unless ptr is NULL (n > 0).
   subroutine put_ints(ptr, n, value)
      type(c_ptr), intent(in) :: ptr
      integer(c_int), intent(in) :: n
      integer, intent(in) :: value
      integer(c_int), pointer :: out(:)
      if (.not. c_associated(ptr)) return
      call c_f_pointer(ptr, out, [n])
      out = int(value, c_int)
   end subroutine put_ints

   !> Copy values into a caller's double array (nothing when there are none).
   subroutine store_reals(ptr, values)
      type(c_ptr), intent(in) :: ptr
      real(c_double), intent(in) :: values(:)
      real(c_double), pointer :: out(:)
      if (size(values) == 0) return
      call c_f_pointer(ptr, out, [size(values)])
      out = values
   end subroutine store_reals

   !> Copy values into a caller's int array (nothing when there are none).
   subroutine store_ints(ptr, values)
      type(c_ptr), intent(in) :: ptr
      integer, intent(in) :: values(:)
      integer(c_int), pointer :: out(:)
      if (size(values) == 0) return
      call c_f_pointer(ptr, out, [size(values)])
      out = int(values, c_int)
   end subroutine store_ints

   !> Copy the message of a call that returned `status` into a C buffer: "" on WA_OK, else
   !> msg (trailing blanks dropped), truncated to capacity - 1 bytes plus a NUL; nothing
   !> when the buffer is NULL or capacity <= 0. The Fortran routines only promise errmsg
   !> on failure: one that recovers from an inner failure (a retry that succeeds) returns
   !> wa_ok with the inner message still in errmsg, which the header's "" on success must
   !> not pass on (wa_gap_law_msg did, e.g. "gap_path: no equilibrium near the branch").
   subroutine copy_message(status, msg, buffer, capacity)
      integer(c_int), intent(in) :: status
      character(len=*), intent(in) :: msg
      type(c_ptr), intent(in) :: buffer
      integer(c_int), intent(in) :: capacity
      character(kind=c_char), pointer :: out(:)
      integer :: n, i

      if (.not. c_associated(buffer) .or. capacity <= 0) return
      call c_f_pointer(buffer, out, [capacity])
      n = min(len_trim(msg), int(capacity) - 1)
      if (status == wa_ok) n = 0
      do i = 1, n
         out(i) = msg(i:i)
      end do
      out(n + 1) = c_null_char
   end subroutine copy_message

   !> int wa_adhesion_map(model, n_alpha, alpha[], mu_lo, mu_hi, capacity,
   !> boundary_code[], alpha_out[], mu_out[], *n_out): the boundary points of the adhesion
   !> map (wa_map), curve after curve, each curve in increasing alpha. *n_out receives the
   !> number of points; when it exceeds capacity the first `capacity` are written and
   !> WA_CAPACITY_TOO_SMALL is returned. On any other failure *n_out = 0 (when n_out is
   !> not NULL) and the arrays are not written.
   function capi_adhesion_map(model, n_alpha, alpha, mu_lo, mu_hi, capacity, boundary_code, &
         alpha_out, mu_out, n_out) result(status) bind(C, name="wa_adhesion_map")
      integer(c_int), value, intent(in) :: model, n_alpha, capacity
      type(c_ptr), value, intent(in) :: alpha, boundary_code, alpha_out, mu_out, n_out
      real(c_double), value, intent(in) :: mu_lo, mu_hi
      integer(c_int) :: status
      status = capi_adhesion_map_control(model, int(map_control_load, c_int), n_alpha, alpha, &
         mu_lo, mu_hi, capacity, boundary_code, alpha_out, mu_out, n_out)
   end function capi_adhesion_map

   !> int wa_adhesion_map_control(model, control, n_alpha, alpha[], mu_lo, mu_hi, capacity,
   !> boundary_code[], alpha_out[], mu_out[], *n_out): wa_adhesion_map with the boundaries
   !> of control WA_MAP_CONTROL_LOAD (1: codes 1xx, 2xx), WA_MAP_CONTROL_GAP (2: gap
   !> control, codes 3xx approach, 4xx retraction) or WA_MAP_CONTROL_BOTH (3).
   function capi_adhesion_map_control(model, control, n_alpha, alpha, mu_lo, mu_hi, capacity, &
         boundary_code, alpha_out, mu_out, n_out) result(status) &
         bind(C, name="wa_adhesion_map_control")
      !> WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> WA_MAP_CONTROL_LOAD, WA_MAP_CONTROL_GAP or WA_MAP_CONTROL_BOTH
      integer(c_int), value, intent(in) :: control
      !> Number of alpha values, >= 1
      integer(c_int), value, intent(in) :: n_alpha
      !> const double[n_alpha]: strictly increasing alpha values
      type(c_ptr), value, intent(in) :: alpha
      !> The mu range, 0 < mu_lo < mu_hi
      real(c_double), value, intent(in) :: mu_lo, mu_hi
      !> Length of the three output arrays, >= 0 (they may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: receives the boundary code of each point
      type(c_ptr), value, intent(in) :: boundary_code
      !> double[capacity]: receive alpha and mu of each point
      type(c_ptr), value, intent(in) :: alpha_out, mu_out
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_out
      integer(c_int) :: status
      integer(c_int), pointer :: n_ptr, codes(:)
      real(c_double), pointer :: a_in(:), a_out(:), m_out(:)
      type(map_type) :: map
      integer :: stat, c, p, n
      character(len=msg_len) :: msg

      msg = ""
      if (c_associated(n_out)) then
         call c_f_pointer(n_out, n_ptr)
         n_ptr = 0
      end if
      status = int(wa_invalid_argument, c_int)
      if (.not. c_associated(n_out) .or. n_alpha < 1 .or. .not. c_associated(alpha) .or. &
         capacity < 0) return
      if (capacity > 0 .and. .not. (c_associated(boundary_code) .and. &
         c_associated(alpha_out) .and. c_associated(mu_out))) return
      call c_f_pointer(alpha, a_in, [n_alpha])
      call adhesion_map(int(model), a_in, mu_lo, mu_hi, 60, map, stat, msg, &
         control=int(control))
      status = int(stat, c_int)
      if (stat /= wa_ok) return
      if (capacity > 0) then
         call c_f_pointer(boundary_code, codes, [capacity])
         call c_f_pointer(alpha_out, a_out, [capacity])
         call c_f_pointer(mu_out, m_out, [capacity])
      end if
      n = 0
      do c = 1, map%n_boundaries
         do p = 1, map%boundary(c)%n
            n = n + 1
            if (n > capacity) cycle
            codes(n) = int(map%boundary(c)%code, c_int)
            a_out(n) = map%boundary(c)%alpha(p)
            m_out(n) = map%boundary(c)%mu(p)
         end do
      end do
      n_ptr = int(n, c_int)
      if (n > capacity) status = int(wa_capacity_too_small, c_int)
   end function capi_adhesion_map_control

   ! ------------------------------------------------------------ gap control

   !> int wa_gap_path(model, alpha, mu, capacity, stage[], event[], zone_case[], a_star[],
   !> c_star[], P_star[], gbar[], *n_events, *W_star, *W_fraction, *g_touch): the events
   !> of the gap-controlled approach (stage 1) and retraction (stage 2) (gap_path), the
   !> energy lost per cycle and the gbar* of the first interaction. When *n_events exceeds
   !> `capacity` the first `capacity` events are written (the three scalars too) and the
   !> status is WA_CAPACITY_TOO_SMALL. On any other failure *n_events = 0 and *W_star =
   !> *W_fraction = *g_touch = NaN (each one that is not NULL).
   function capi_gap_path(model, alpha, mu, capacity, stage, event, zone_case, a_star, &
         c_star, p_star, gbar, n_events, w_star, w_fraction, g_touch) result(status) &
         bind(C, name="wa_gap_path")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the seven arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: stage (WA_STAGE_APPROACH, WA_STAGE_RETRACTION), event code
      !> (WA_GAP_EVENT_*) and zone case of each event
      type(c_ptr), value, intent(in) :: stage, event, zone_case
      !> double[capacity]: a*, c*, P* and gbar* of each event
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star, gbar
      !> int *: receives the number of events
      type(c_ptr), value, intent(in) :: n_events
      !> double *: receive W*, W*/(pi alpha^2/2) and the gbar* of the first interaction
      type(c_ptr), value, intent(in) :: w_star, w_fraction, g_touch
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call gap_path_core(model, alpha, mu, capacity, [stage, event, zone_case], &
         [a_star, c_star, p_star, gbar], n_events, [w_star, w_fraction, g_touch], status, msg)
   end function capi_gap_path

   !> int wa_gap_path_msg(..., char *message, int message_capacity): as wa_gap_path, with
   !> the message of wa_equilibrium_msg.
   function capi_gap_path_msg(model, alpha, mu, capacity, stage, event, zone_case, a_star, &
         c_star, p_star, gbar, n_events, w_star, w_fraction, g_touch, message, &
         message_capacity) result(status) bind(C, name="wa_gap_path_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Length of the seven arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: stage, event code and zone case of each event
      type(c_ptr), value, intent(in) :: stage, event, zone_case
      !> double[capacity]: a*, c*, P* and gbar* of each event
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star, gbar
      !> int *: receives the number of events
      type(c_ptr), value, intent(in) :: n_events
      !> double *: receive W*, W*/(pi alpha^2/2) and the gbar* of the first interaction
      type(c_ptr), value, intent(in) :: w_star, w_fraction, g_touch
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call gap_path_core(model, alpha, mu, capacity, [stage, event, zone_case], &
         [a_star, c_star, p_star, gbar], n_events, [w_star, w_fraction, g_touch], status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_gap_path_msg

   !> int wa_gap_law(model, alpha, mu, n, gbar[], P_approach[], P_retract[],
   !> dPdg_approach[], dPdg_retract[]): the gap law (gap_law) at n mean gaps. On any
   !> failure, when n > 0, every element of each output array that is not NULL is NaN.
   function capi_gap_law(model, alpha, mu, n, gbar, p_approach, p_retract, dpdg_approach, &
         dpdg_retract) result(status) bind(C, name="wa_gap_law")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Number of mean gaps, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n
      !> const double[n]: mean gaps gbar*, each finite and >= 0
      type(c_ptr), value, intent(in) :: gbar
      !> double[n]: P* on approach and on retraction
      type(c_ptr), value, intent(in) :: p_approach, p_retract
      !> double[n]: dP*/dgbar* on approach and on retraction
      type(c_ptr), value, intent(in) :: dpdg_approach, dpdg_retract
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call gap_law_core(model, alpha, mu, n, gbar, [p_approach, p_retract, dpdg_approach, &
         dpdg_retract], status, msg)
   end function capi_gap_law

   !> int wa_gap_law_msg(..., char *message, int message_capacity): as wa_gap_law, with
   !> the message of wa_equilibrium_msg.
   function capi_gap_law_msg(model, alpha, mu, n, gbar, p_approach, p_retract, &
         dpdg_approach, dpdg_retract, message, message_capacity) result(status) &
         bind(C, name="wa_gap_law_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> Number of mean gaps, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n
      !> const double[n]: mean gaps gbar*, each finite and >= 0
      type(c_ptr), value, intent(in) :: gbar
      !> double[n]: P* on approach and on retraction
      type(c_ptr), value, intent(in) :: p_approach, p_retract
      !> double[n]: dP*/dgbar* on approach and on retraction
      type(c_ptr), value, intent(in) :: dpdg_approach, dpdg_retract
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call gap_law_core(model, alpha, mu, n, gbar, [p_approach, p_retract, dpdg_approach, &
         dpdg_retract], status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_gap_law_msg

   !> int wa_gap_critical(model, alpha, mu, values[WA_GAP_CRITICAL_COUNT]): the critical
   !> values under gap control (gap_critical), in the order WA_GAP_CRITICAL_G_TOUCH ...
   !> WA_GAP_CRITICAL_G_INTERACTION_LOST. On any failure every element of values (when
   !> it is not NULL) is NaN.
   function capi_gap_critical(model, alpha, mu, values) result(status) &
         bind(C, name="wa_gap_critical")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> double[WA_GAP_CRITICAL_COUNT]: receives the values
      type(c_ptr), value, intent(in) :: values
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call gap_critical_core(model, alpha, mu, values, status, msg)
   end function capi_gap_critical

   !> int wa_gap_critical_msg(..., char *message, int message_capacity): as
   !> wa_gap_critical, with the message of wa_equilibrium_msg.
   function capi_gap_critical_msg(model, alpha, mu, values, message, message_capacity) &
         result(status) bind(C, name="wa_gap_critical_msg")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter, > 0
      real(c_double), value, intent(in) :: alpha
      !> Transition parameter, >= 0
      real(c_double), value, intent(in) :: mu
      !> double[WA_GAP_CRITICAL_COUNT]: receives the values
      type(c_ptr), value, intent(in) :: values
      !> char *: receives the message (may be NULL)
      type(c_ptr), value, intent(in) :: message
      !> Size of `message` in bytes, NUL included
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      character(len=msg_len) :: msg
      call gap_critical_core(model, alpha, mu, values, status, msg)
      call copy_message(status, msg, message, message_capacity)
   end function capi_gap_critical_msg

   !> Validate, follow the gap-controlled cycle, write min(n, capacity) events, n and the
   !> scalars. ints = [stage, event, zone_case], reals = [a_star, c_star, P_star, gbar],
   !> scalars = [W_star, W_fraction, g_touch].
   subroutine gap_path_core(model, alpha, mu, capacity, ints, reals, n_events, scalars, &
         status, msg)
      integer(c_int), intent(in) :: model, capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: ints(3), reals(4), n_events, scalars(3)
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      integer(c_int), pointer :: n_out
      real(c_double), pointer :: out
      type(params_type) :: params
      type(gap_path_type) :: path
      real(c_double) :: values(3)
      integer :: stat, m, k

      msg = ""
      call put_int(n_events, 0)
      do k = 1, 3
         call put_nan(scalars(k))
      end do
      call check_outputs("n_events", n_events, "capacity", capacity, [ints, reals], &
         "stage, event, zone_case, a_star, c_star, P_star and gbar", stat, msg)
      if (stat == wa_ok .and. .not. (c_associated(scalars(1)) .and. &
         c_associated(scalars(2)) .and. c_associated(scalars(3)))) &
         call set_error(wa_invalid_argument, "W_star, W_fraction and g_touch must not "// &
         "be NULL", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call gap_path(int(model), params, path, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) call check_gbar_values(path%gbar(1:path%n), stat, msg)
      if (stat == wa_ok) then
         m = min(path%n, int(capacity))
         call store_ints(ints(1), path%stage(1:m))
         call store_ints(ints(2), path%event(1:m))
         call store_ints(ints(3), path%zone_case(1:m))
         call store_reals(reals(1), path%a_star(1:m))
         call store_reals(reals(2), path%c_star(1:m))
         call store_reals(reals(3), path%p_star(1:m))
         call store_reals(reals(4), path%gbar(1:m))
         call c_f_pointer(n_events, n_out)
         n_out = int(path%n, c_int)
         values = [path%w_star, path%w_fraction, path%g_touch]
         do k = 1, 3
            call c_f_pointer(scalars(k), out)
            out = values(k)
         end do
         if (path%n > capacity) call too_small("the gap path has", "events", path%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
   end subroutine gap_path_core

   !> Validate everything (every gbar first), then the gap law at n mean gaps (every
   !> element of the outputs NaN on any failure, when n > 0 and they are not NULL).
   !> outs = [P_approach, P_retract, dPdg_approach, dPdg_retract].
   subroutine gap_law_core(model, alpha, mu, n, gbar, outs, status, msg)
      use wa_validate, only: check_range
      integer(c_int), intent(in) :: model, n
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: gbar, outs(4)
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      real(c_double), pointer :: g_in(:)
      real(c_double), allocatable :: res(:, :)
      type(params_type) :: params
      integer :: stat, k
      character(len=12) :: text

      msg = ""
      if (n > 0) then
         do k = 1, 4
            call put_nans(outs(k), n)
         end do
      end if
      call check_outputs("", gbar, "n", n, [gbar, outs], &
         "gbar, P_approach, P_retract, dPdg_approach and dPdg_retract", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok .and. n > 0) then         ! every argument before any work
         call c_f_pointer(gbar, g_in, [n])
         do k = 1, int(n)
            write (text, '(i0)') k - 1
            call check_range("gbar["//trim(text)//"]", g_in(k), 0.0_c_double, &
               huge(1.0_c_double), "[0, inf) (the mean gap over the wave "// &
               "amplitude)", stat, msg)
            if (stat /= wa_ok) exit
         end do
      end if
      if (stat == wa_ok) then
         allocate (res(max(0, n), 4))
         if (n > 0) then
            call gap_law(int(model), params, g_in, res(:, 1), res(:, 2), res(:, 3), &
               res(:, 4), stat, msg)
         else
            call gap_law(int(model), params, [real(c_double) ::], res(:, 1), res(:, 2), &
               res(:, 3), res(:, 4), stat, msg)
         end if
         call internal_capacity(stat, msg)
         if (stat == wa_ok .and. n > 0) then
            if (any(res(:, 1:2) /= res(:, 1:2)) .or. any(res(:, 3:4) /= res(:, 3:4))) &
               call set_error(wa_numerical_error, "gap_law: a value is NaN", stat, msg)
         end if
         if (stat == wa_ok .and. n > 0) then
            do k = 1, 4
               call store_reals(outs(k), res(:, k))
            end do
         end if
      end if
      status = int(stat, c_int)
   end subroutine gap_law_core

   !> Validate, compute the critical values under gap control (NaN on failure).
   subroutine gap_critical_core(model, alpha, mu, values, status, msg)
      integer(c_int), intent(in) :: model
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: values
      integer(c_int), intent(out) :: status
      character(len=*), intent(out) :: msg
      type(params_type) :: params
      type(gap_critical_type) :: crit
      integer :: stat

      msg = ""
      call put_nans(values, int(gap_critical_count, c_int))
      if (.not. c_associated(values)) then
         call set_error(wa_invalid_argument, "values must not be NULL", stat, msg)
         status = int(stat, c_int)
         return
      end if
      call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call gap_critical(int(model), params, crit, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) call store_reals(values, gap_critical_values(crit))
      status = int(stat, c_int)
   end subroutine gap_critical_core

end module wa_capi
