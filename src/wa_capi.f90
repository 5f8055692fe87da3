!> display: none
!>
!> The C interface (doc/c-api.md), part 1: the closed-form loads, states (equilibrium,
!> roots), the branch, load control (critical forces, load path, sweep), profiles, the
!> status texts and the version. Gap control is in wa_capi_gap, the adhesion map in
!> wa_capi_map, smooth adhesion in wa_capi_lj, the 0.2 names in wa_capi_compat; the
!> declarations in include/wavyadhesion.h.
!>
!> One function per capability: optional outputs (the mean gap gbar, a sweep's row
!> statuses) are pointers that may be NULL, and every function taking pointers ends with
!> `char *message, int message_capacity` (NULL/0 allowed; "" on success). Each export is
!> one call of its `*_core` routine, which the 0.2 forwards of wa_capi_compat call too.
!> Every function taking pointers returns an `int` status (0 = ok) and writes its results
!> through the pointers; arrays are caller-allocated with an explicit capacity; nothing
!> is allocated for the caller to free. NULL result pointers are reported as
!> wa_invalid_argument, never dereferenced.
!> Thread safe: no state survives a call (the status texts are immutable data).
module wa_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_char, &
      c_associated, c_f_pointer, c_loc
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_status, only: wa_ok, wa_invalid_argument, wa_capacity_too_small, &
      wa_numerical_error, set_error
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_kernels, only: westergaard_load, jkr_load
   use wa_models, only: check_model, model_equilibrium, model_roots, model_profile
   use wa_branch, only: branch_type, trace_branch
   use wa_loadpath, only: path_type, load_path, critical_forces, critical_sweep
   use wa_release, only: wa_version
   use wa_capi_util, only: msg_len, copy_message, check_outputs, too_small, &
      internal_capacity, check_gbar_values, put_nan, put_int, put_nans, put_ints, &
      store_reals, store_ints
   implicit none
   private

   public :: capi_westergaard_load, capi_jkr_load, capi_equilibrium, capi_roots, &
      capi_trace_branch, capi_critical_forces, capi_load_path, capi_critical_sweep, &
      capi_profile, capi_status_message, capi_version
   public :: equilibrium_core, roots_core, branch_core, critical_core, path_core, &
      sweep_core, profile_core

   !> Length of one status text, NUL included.
   integer, parameter :: text_len = 32
   !> Largest status code with a text of its own; others read "unknown status".
   integer, parameter :: last_status = wa_numerical_error
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

   !> int wa_equilibrium(model, alpha, mu, a_star, *c_star, *P_star, *zone_case, *gbar,
   !> message, message_capacity): the principal equilibrium, and its mean gap when gbar
   !> is not NULL. On failure *c_star = *P_star = *gbar = NaN, *zone_case = 0.
   function capi_equilibrium(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar, &
         message, message_capacity) result(status) bind(C, name="wa_equilibrium")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> double *, double *, int *: receive c*, P* and the zone case
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case
      !> double * or NULL: receives the mean gap gbar*
      type(c_ptr), value, intent(in) :: gbar
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar, &
         c_associated(gbar), message, message_capacity)
   end function capi_equilibrium

   !> int wa_roots(model, alpha, mu, a_star, capacity, c_star[], P_star[], zone_case[],
   !> gbar[], *n_roots, message, message_capacity): every equilibrium at a* (and each
   !> one's mean gap when gbar is not NULL). *n_roots is the total; when it exceeds
   !> `capacity`, the first `capacity` states are written and the status is
   !> WA_CAPACITY_TOO_SMALL. On any other failure *n_roots = 0.
   function capi_roots(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, gbar, &
         n_roots, message, message_capacity) result(status) bind(C, name="wa_roots")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Contact half-width over the period, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity], double[capacity], int[capacity]: c*, P*, zone case of each state
      type(c_ptr), value, intent(in) :: c_star, p_star, zone_case
      !> double[capacity] or NULL: the mean gap of each state
      type(c_ptr), value, intent(in) :: gbar
      !> int *: receives the number of states
      type(c_ptr), value, intent(in) :: n_roots
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, &
         gbar, c_associated(gbar), n_roots, message, message_capacity)
   end function capi_roots

   !> int wa_trace_branch(model, alpha, mu, capacity, a_star[], c_star[], P_star[],
   !> zone_case[], stable[], event[], gbar[], *n_points, message, message_capacity): the
   !> equilibrium branch by continuation (trace_branch), in the order of the curve, and
   !> each point's mean gap when gbar is not NULL. *n_points is the number of points; when
   !> it exceeds `capacity` the first `capacity` points are written and the status is
   !> WA_CAPACITY_TOO_SMALL. On any other failure *n_points = 0.
   function capi_trace_branch(model, alpha, mu, capacity, a_star, c_star, p_star, &
         zone_case, stable, event, gbar, n_points, message, message_capacity) result(status) &
         bind(C, name="wa_trace_branch")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Length of the arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: a*, c* and P* of each point
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star
      !> int[capacity]: zone case, stability under load control (1/0), event (WA_EVENT_*)
      type(c_ptr), value, intent(in) :: zone_case, stable, event
      !> double[capacity] or NULL: the mean gap of each point
      type(c_ptr), value, intent(in) :: gbar
      !> int *: receives the number of points
      type(c_ptr), value, intent(in) :: n_points
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = branch_core(model, alpha, mu, capacity, [a_star, c_star, p_star], gbar, &
         c_associated(gbar), [zone_case, stable, event], n_points, message, message_capacity)
   end function capi_trace_branch

   !> int wa_critical_forces(model, alpha, mu, *P_fc, *P_pf, message, message_capacity):
   !> the load at which full contact is first reached on loading from P* = 0 and the
   !> pull-off load on unloading from full contact (JKR: -Infinity). On failure
   !> *P_fc = *P_pf = NaN.
   function capi_critical_forces(model, alpha, mu, p_fc, p_pf, message, message_capacity) &
         result(status) bind(C, name="wa_critical_forces")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> double *: receive P_fc* and P_pf*
      type(c_ptr), value, intent(in) :: p_fc, p_pf
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = critical_core(model, alpha, mu, p_fc, p_pf, message, message_capacity)
   end function capi_critical_forces

   !> int wa_load_path(model, alpha, mu, capacity, stage[], event[], a_star[], c_star[],
   !> P_star[], *n_events, *P_fc, *P_pf, message, message_capacity): the events of
   !> load-controlled loading (stage 1) and unloading (stage 2), with P_fc* and P_pf*.
   !> *n_events is the number of events; when it exceeds `capacity` the first `capacity`
   !> are written (P_fc, P_pf too) and the status is WA_CAPACITY_TOO_SMALL. On any other
   !> failure *n_events = 0 and *P_fc = *P_pf = NaN.
   function capi_load_path(model, alpha, mu, capacity, stage, event, a_star, c_star, &
         p_star, n_events, p_fc, p_pf, message, message_capacity) result(status) &
         bind(C, name="wa_load_path")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Length of the arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> int[capacity]: stage (WA_STAGE_*) and event code (WA_EVENT_*) of each event
      type(c_ptr), value, intent(in) :: stage, event
      !> double[capacity]: a*, c* and P* of each event
      type(c_ptr), value, intent(in) :: a_star, c_star, p_star
      !> int *: receives the number of events
      type(c_ptr), value, intent(in) :: n_events
      !> double *: receive P_fc* and P_pf*
      type(c_ptr), value, intent(in) :: p_fc, p_pf
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = path_core(model, alpha, mu, capacity, [stage, event], [a_star, c_star, p_star], &
         n_events, p_fc, p_pf, message, message_capacity)
   end function capi_load_path

   !> int wa_critical_sweep(model, alpha, n_mu, mu[], P_fc[], P_pf[], fc_mechanism[],
   !> pf_mechanism[], row_status[], message, message_capacity): P_fc*, P_pf* and how each
   !> is reached (WA_MECHANISM_*) for one alpha over n_mu values of mu. Every argument
   !> (every mu) is validated before any work; an invalid one writes NaN (mechanisms -1)
   !> everywhere. A mu whose load path fails gets NaN (-1) in its row only; every other
   !> row is written and the status of the first failing row is returned; row_status
   !> (when not NULL) receives each row's status.
   function capi_critical_sweep(model, alpha, n_mu, mu, p_fc, p_pf, fc_mechanism, &
         pf_mechanism, row_status, message, message_capacity) result(status) &
         bind(C, name="wa_critical_sweep")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha
      !> Number of mu values, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n_mu
      !> const double[n_mu]: transition parameters (the supported domain)
      type(c_ptr), value, intent(in) :: mu
      !> double[n_mu]: receive P_fc* and P_pf*
      type(c_ptr), value, intent(in) :: p_fc, p_pf
      !> int[n_mu]: receive how full contact is reached and how contact is lost
      type(c_ptr), value, intent(in) :: fc_mechanism, pf_mechanism
      !> int[n_mu] or NULL: receives the status of each row
      type(c_ptr), value, intent(in) :: row_status
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = sweep_core(model, alpha, n_mu, mu, [p_fc, p_pf], [fc_mechanism, pf_mechanism], &
         row_status, c_associated(row_status), message, message_capacity)
   end function capi_critical_sweep

   !> int wa_profile(model, alpha, mu, a_star, c_star, n, x_star[], traction[], gap[],
   !> message, message_capacity): the traction p/p* and the gap h/Delta at n points x* of
   !> the state at a* identified by c* (wa_models::model_state: the root at a* with the
   !> nearest c*, within 1e-6; MD at a* = 0: the no-contact state with zone half-width
   !> c* < 1/2). On any failure, when n > 0, every element of traction and gap (each not
   !> NULL) is NaN.
   function capi_profile(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         message, message_capacity) result(status) bind(C, name="wa_profile")
      !> WA_MODEL_WESTERGAARD, WA_MODEL_JKR, WA_MODEL_DW or WA_MODEL_MD
      integer(c_int), value, intent(in) :: model
      !> Johnson's parameter and the transition parameter (the supported domain)
      real(c_double), value, intent(in) :: alpha, mu
      !> Contact half-width and interaction-zone half-width of the state, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star, c_star
      !> Number of points, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: n
      !> const double[n]: the points x* (any finite values; period 1, crest at 0)
      type(c_ptr), value, intent(in) :: x_star
      !> double[n]: receive p/p* (positive = compressive) and h/Delta (>= 0)
      type(c_ptr), value, intent(in) :: traction, gap
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = profile_core(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         message, message_capacity)
   end function capi_profile

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

   ! ---------------------------------------------------------------- cores

   !> Validate, solve, write the principal state (NaN, NaN, 0 on failure); with want_gbar
   !> also its mean gap (NaN on failure; gbar NULL is then WA_INVALID_ARGUMENT).
   function equilibrium_core(model, alpha, mu, a_star, c_star, p_star, zone_case, gbar, &
         want_gbar, message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, message_capacity
      real(c_double), intent(in) :: alpha, mu, a_star
      type(c_ptr), intent(in) :: c_star, p_star, zone_case, gbar, message
      logical, intent(in) :: want_gbar
      integer(c_int) :: status
      real(c_double), pointer :: c_out, p_out, g_out
      integer(c_int), pointer :: z_out
      type(params_type) :: params
      type(state_type) :: state
      integer :: stat
      character(len=msg_len) :: msg

      msg = ""
      stat = wa_ok
      call put_nan(c_star)
      call put_nan(p_star)
      call put_int(zone_case, 0)
      if (want_gbar) call put_nan(gbar)
      if (.not. (c_associated(c_star) .and. c_associated(p_star) .and. &
            c_associated(zone_case))) then
         call set_error(wa_invalid_argument, "c_star, P_star and zone_case must not be NULL", &
            stat, msg)
      else if (want_gbar .and. .not. c_associated(gbar)) then
         call set_error(wa_invalid_argument, "gbar must not be NULL", stat, msg)
      end if
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call model_equilibrium(int(model), params, a_star, state, stat, msg)
      if (stat == wa_ok .and. want_gbar) then
         call check_gbar_values([state%gbar], stat, msg)
         if (stat == wa_ok) then
            call c_f_pointer(gbar, g_out)
            g_out = state%gbar
         end if
      end if
      if (stat == wa_ok) then
         call c_f_pointer(c_star, c_out)
         call c_f_pointer(p_star, p_out)
         call c_f_pointer(zone_case, z_out)
         c_out = state%c_star
         p_out = state%p_star
         z_out = int(state%zone_case, c_int)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function equilibrium_core

   !> Validate, solve, write min(n, capacity) states and n (0 on failures other than
   !> a too small capacity); with want_gbar also their mean gaps.
   function roots_core(model, alpha, mu, a_star, capacity, c_star, p_star, zone_case, gbar, &
         want_gbar, n_roots, message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, capacity, message_capacity
      real(c_double), intent(in) :: alpha, mu, a_star
      type(c_ptr), intent(in) :: c_star, p_star, zone_case, gbar, n_roots, message
      logical, intent(in) :: want_gbar
      integer(c_int) :: status
      integer(c_int), pointer :: n_out
      type(params_type) :: params
      type(state_type), allocatable :: states(:)
      integer :: stat, n, m
      character(len=msg_len) :: msg

      msg = ""
      n = 0
      call put_int(n_roots, 0)
      call check_outputs("n_roots", n_roots, "capacity", capacity, [c_star, p_star, zone_case], &
         "c_star, P_star and zone_case", stat, msg)
      if (stat == wa_ok .and. want_gbar .and. capacity > 0 .and. .not. c_associated(gbar)) &
         call set_error(wa_invalid_argument, "gbar must not be NULL when capacity > 0", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
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
      if (stat == wa_ok .or. stat == wa_capacity_too_small) then
         m = min(n, size(states))
         if (want_gbar) then
            call check_gbar_values(states(1:m)%gbar, stat, msg)
            if (stat /= wa_ok .and. stat /= wa_capacity_too_small) n = 0
         end if
      end if
      if (stat == wa_ok .or. stat == wa_capacity_too_small) then
         call store_reals(c_star, states(1:m)%c_star)
         call store_reals(p_star, states(1:m)%p_star)
         call store_ints(zone_case, states(1:m)%zone_case)
         if (want_gbar) call store_reals(gbar, states(1:m)%gbar)
         call c_f_pointer(n_roots, n_out)
         n_out = int(n, c_int)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function roots_core

   !> Validate, trace, write min(n, capacity) points and n (0 on failures other than a
   !> too small capacity). reals = [a_star, c_star, P_star], ints = [zone_case, stable,
   !> event]; with want_gbar also each point's mean gap.
   function branch_core(model, alpha, mu, capacity, reals, gbar, want_gbar, ints, n_points, &
         message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, capacity, message_capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: reals(3), gbar, ints(3), n_points, message
      logical, intent(in) :: want_gbar
      integer(c_int) :: status
      integer(c_int), pointer :: n_out
      type(params_type) :: params
      type(branch_type) :: branch
      integer :: stat, m
      character(len=msg_len) :: msg

      msg = ""
      call put_int(n_points, 0)
      if (want_gbar) then
         call check_outputs("n_points", n_points, "capacity", capacity, [reals, gbar, ints], &
            "a_star, c_star, P_star, zone_case, stable, event and gbar", stat, msg)
      else
         call check_outputs("n_points", n_points, "capacity", capacity, [reals, ints], &
            "a_star, c_star, P_star, zone_case, stable and event", stat, msg)
      end if
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call trace_branch(int(model), params, branch, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok .and. want_gbar) call check_gbar_values(branch%gbar(1:branch%n), &
         stat, msg)
      if (stat == wa_ok) then
         m = min(branch%n, int(capacity))
         if (want_gbar) call store_reals(gbar, branch%gbar(1:m))
         call store_reals(reals(1), branch%a_star(1:m))
         call store_reals(reals(2), branch%c_star(1:m))
         call store_reals(reals(3), branch%p_star(1:m))
         call store_ints(ints(1), branch%zone_case(1:m))
         call store_ints(ints(2), merge(1, 0, branch%stable(1:m)))
         call store_ints(ints(3), branch%event(1:m))
         call c_f_pointer(n_points, n_out)
         n_out = int(branch%n, c_int)
         if (branch%n > capacity) call too_small("the branch has", "points", branch%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function branch_core

   !> Validate, compute P_fc* and P_pf* (NaN on failure).
   function critical_core(model, alpha, mu, p_fc, p_pf, message, message_capacity) &
         result(status)
      integer(c_int), intent(in) :: model, message_capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: p_fc, p_pf, message
      integer(c_int) :: status
      real(c_double), pointer :: fc_out, pf_out
      type(params_type) :: params
      real(c_double) :: fc, pf
      integer :: stat
      character(len=msg_len) :: msg

      msg = ""
      stat = wa_ok
      call put_nan(p_fc)
      call put_nan(p_pf)
      if (.not. (c_associated(p_fc) .and. c_associated(p_pf))) &
         call set_error(wa_invalid_argument, "P_fc and P_pf must not be NULL", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
      if (stat == wa_ok) call new_params(alpha, mu, params, stat, msg)
      if (stat == wa_ok) call critical_forces(int(model), params, fc, pf, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         call c_f_pointer(p_fc, fc_out)
         call c_f_pointer(p_pf, pf_out)
         fc_out = fc
         pf_out = pf
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function critical_core

   !> Validate, follow the load path, write min(n, capacity) events, n, P_fc*, P_pf*.
   !> ints = [stage, event], reals = [a_star, c_star, P_star].
   function path_core(model, alpha, mu, capacity, ints, reals, n_events, p_fc, p_pf, &
         message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, capacity, message_capacity
      real(c_double), intent(in) :: alpha, mu
      type(c_ptr), intent(in) :: ints(2), reals(3), n_events, p_fc, p_pf, message
      integer(c_int) :: status
      integer(c_int), pointer :: n_out
      real(c_double), pointer :: fc_out, pf_out
      type(params_type) :: params
      type(path_type) :: path
      integer :: stat, m
      character(len=msg_len) :: msg

      msg = ""
      call put_int(n_events, 0)
      call put_nan(p_fc)
      call put_nan(p_pf)
      call check_outputs("n_events", n_events, "capacity", capacity, [ints, reals], &
         "stage, event, a_star, c_star and P_star", stat, msg)
      if (stat == wa_ok .and. .not. (c_associated(p_fc) .and. c_associated(p_pf))) &
         call set_error(wa_invalid_argument, "P_fc and P_pf must not be NULL", stat, msg)
      if (stat == wa_ok) call check_model(int(model), stat, msg)
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
         call c_f_pointer(n_events, n_out)
         call c_f_pointer(p_fc, fc_out)
         call c_f_pointer(p_pf, pf_out)
         n_out = int(path%n, c_int)
         fc_out = path%p_fc
         pf_out = path%p_pf
         if (path%n > capacity) call too_small("the load path has", "events", path%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function path_core

   !> Validate everything (every mu first), then sweep: a failing mu leaves NaN and -1 in
   !> its row only (an invalid argument: in every row). reals = [P_fc, P_pf],
   !> ints = [fc_mechanism, pf_mechanism]; rows = row_status, written and required
   !> (non-NULL when n_mu > 0) when want_rows.
   function sweep_core(model, alpha, n_mu, mu, reals, ints, rows, want_rows, message, &
         message_capacity) result(status)
      integer(c_int), intent(in) :: model, n_mu, message_capacity
      real(c_double), intent(in) :: alpha
      type(c_ptr), intent(in) :: mu, reals(2), ints(2), rows, message
      logical, intent(in) :: want_rows
      integer(c_int) :: status
      real(c_double), pointer :: mu_in(:), fc_out(:), pf_out(:)
      integer(c_int), pointer :: fcm_out(:), pfm_out(:), rows_out(:)
      real(c_double), allocatable :: p_fc(:), p_pf(:)
      integer, allocatable :: fc_mech(:), pf_mech(:), row_stat(:)
      type(params_type) :: params
      integer :: stat, i
      logical :: pointers_ok
      character(len=12) :: text
      character(len=msg_len) :: msg

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
      pointers_ok = stat == wa_ok
      if (.not. pointers_ok) then
         if (want_rows .and. n_mu > 0) call put_ints(rows, n_mu, stat)
      else
         call check_model(int(model), stat, msg)
         if (stat == wa_ok) call new_params(alpha, 0.0_c_double, params, stat, msg)
      end if
      if (n_mu > 0 .and. pointers_ok) then
         call c_f_pointer(mu, mu_in, [n_mu])
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
            call critical_sweep(int(model), alpha, mu_in, p_fc, p_pf, fc_mech, pf_mech, &
               stat, msg, row_stat)
            call internal_capacity(stat, msg)
            where (row_stat == wa_capacity_too_small) row_stat = wa_numerical_error
            call c_f_pointer(reals(1), fc_out, [n_mu])   ! every row: NaN, -1 where one failed
            call c_f_pointer(reals(2), pf_out, [n_mu])
            call c_f_pointer(ints(1), fcm_out, [n_mu])
            call c_f_pointer(ints(2), pfm_out, [n_mu])
            fc_out = p_fc
            pf_out = p_pf
            fcm_out = int(fc_mech, c_int)
            pfm_out = int(pf_mech, c_int)
         end if
         if (want_rows) then
            call c_f_pointer(rows, rows_out, [n_mu])
            rows_out = int(row_stat, c_int)
         end if
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function sweep_core

   !> Validate, identify the state (model_state), write its profile at n points (every
   !> element of traction and gap NaN on any failure, when n > 0 and they are not NULL).
   function profile_core(model, alpha, mu, a_star, c_star, n, x_star, traction, gap, &
         message, message_capacity) result(status)
      integer(c_int), intent(in) :: model, n, message_capacity
      real(c_double), intent(in) :: alpha, mu, a_star, c_star
      type(c_ptr), intent(in) :: x_star, traction, gap, message
      integer(c_int) :: status
      real(c_double), pointer :: x_in(:)
      real(c_double), allocatable :: t(:), g(:)
      type(params_type) :: params
      type(state_type) :: state
      integer :: stat, k
      character(len=12) :: text
      character(len=msg_len) :: msg

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
         if (stat == wa_ok) then
            call store_reals(traction, t)
            call store_reals(gap, g)
         end if
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function profile_core

end module wa_capi
