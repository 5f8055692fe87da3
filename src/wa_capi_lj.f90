!> display: none
!>
!> The C interface, smooth adhesion (the self-consistent Lennard-Jones model): the cycle
!> with its critical values and error estimates, the traced equilibrium curve and the
!> gap and traction of the state at a given a* (declarations in include/wavyadhesion.h;
!> the conventions in wa_capi). Each export is one call of its `*_core` routine.
module wa_capi_lj
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_ptr, c_associated, c_f_pointer
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, wa_capacity_too_small, set_error
   use wa_params, only: params_type, new_params
   use wa_bem_solver, only: lj_problem_type, lj_problem
   use wa_bem_trace, only: lj_branch_type, lj_trace
   use wa_bem_path, only: lj_cycle_type, lj_cycle
   use wa_bem_state, only: lj_state_type, lj_state_at_a
   use wa_capi_util, only: msg_len, copy_message, check_outputs, too_small, &
      internal_capacity, put_nan, put_int, put_nans, store_reals, store_ints, store_scalar
   implicit none
   private

   public :: capi_lj_cycle, capi_lj_trace, capi_lj_profile
   public :: lj_cycle_core, lj_trace_core, lj_profile_core

contains

   !> int wa_lj_cycle(alpha, mu, n, n_profile, profile, *P_fc, *P_pf, *P_snap, *W_star,
   !> *P_fc_peak, errors[5], *n_used, message, message_capacity): the load- and
   !> gap-controlled cycle of the smooth (Lennard-Jones) model (lj_cycle) on the grid of n
   !> points per period (0: automatic), with the error estimates |value at N - value at
   !> N/2|. On any failure the five scalars and errors (each not NULL) are NaN and
   !> *n_used = 0.
   function capi_lj_cycle(alpha, mu, n, n_profile, profile, p_fc, p_pf, p_snap, w_star, &
         p_fc_peak, errors, n_used, message, message_capacity) result(status) &
         bind(C, name="wa_lj_cycle")
      !> Johnson's parameter and the transition parameter (the supported domain, mu > 0)
      real(c_double), value, intent(in) :: alpha, mu
      !> Grid points per period: 0 (automatic) or a multiple of 4, >= 16
      integer(c_int), value, intent(in) :: n
      !> Number of profile samples, >= 4 when profile is not NULL (else ignored)
      integer(c_int), value, intent(in) :: n_profile
      !> const double[n_profile] or NULL (the sinusoid): heights over Delta at x* = j/n_profile
      type(c_ptr), value, intent(in) :: profile
      !> double *: receive P_fc*, P_pf*, the snap load (over p*) and W* (over p* Delta)
      type(c_ptr), value, intent(in) :: p_fc, p_pf, p_snap, w_star
      !> double * or NULL: receives P_fc,peak*, the load at which b* first reaches 1/2 on
      !> loading (the full-contact load comparable with DW's and MD's P_fc*)
      type(c_ptr), value, intent(in) :: p_fc_peak
      !> double[5] or NULL: the error estimates of the same five
      type(c_ptr), value, intent(in) :: errors
      !> int * or NULL: the grid points per period used
      type(c_ptr), value, intent(in) :: n_used
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = lj_cycle_core(alpha, mu, n, n_profile, profile, [p_fc, p_pf, p_snap, w_star, &
         p_fc_peak], errors, n_used, message, message_capacity)
   end function capi_lj_cycle

   !> int wa_lj_trace(alpha, mu, n, n_profile, profile, capacity, P_star[], gbar[],
   !> a_star[], b_star[], stable_load[], stable_gap[], event[], *n_points, *n_used, message,
   !> message_capacity): the traced equilibrium curve of the smooth (Lennard-Jones) model
   !> (lj_trace). When *n_points exceeds capacity the first capacity points are written and
   !> the status is WA_CAPACITY_TOO_SMALL. On any other failure *n_points = *n_used = 0.
   function capi_lj_trace(alpha, mu, n, n_profile, profile, capacity, p_star, gbar, a_star, &
         b_star, stable_load, stable_gap, event, n_points, n_used, message, message_capacity) &
         result(status) bind(C, name="wa_lj_trace")
      !> Johnson's parameter and the transition parameter (the supported domain, mu > 0)
      real(c_double), value, intent(in) :: alpha, mu
      !> Grid points per period: 0 (automatic) or even, >= 8
      integer(c_int), value, intent(in) :: n
      !> Number of profile samples, >= 4 when profile is not NULL (else ignored)
      integer(c_int), value, intent(in) :: n_profile
      !> const double[n_profile] or NULL (the sinusoid): heights over Delta at x* = j/n_profile
      type(c_ptr), value, intent(in) :: profile
      !> Length of the arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: P*, gbar* (over Delta), a*, b* of each point
      type(c_ptr), value, intent(in) :: p_star, gbar, a_star, b_star
      !> int[capacity] or NULL: 1 where stable under load / gap control, else 0; the event
      !> code of each point
      type(c_ptr), value, intent(in) :: stable_load, stable_gap, event
      !> int *: receives the number of points; int * or NULL: the grid points per period
      type(c_ptr), value, intent(in) :: n_points, n_used
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = lj_trace_core(alpha, mu, n, n_profile, profile, capacity, &
         [p_star, gbar, a_star, b_star], [stable_load, stable_gap, event], n_points, n_used, &
         message, message_capacity)
   end function capi_lj_trace

   !> int wa_lj_profile(alpha, mu, n, n_profile, profile, a_star, capacity, x_star[],
   !> traction[], gap[], state[4], *n_points, message, message_capacity): the gap and
   !> traction at the N grid nodes (x* from -1/2) of the traced state with a* nearest a_star,
   !> among the load-stable states when there are any (lj_state_at_a). When N exceeds
   !> capacity the first capacity points are written and the status is
   !> WA_CAPACITY_TOO_SMALL. On any other failure *n_points = 0 and state is NaN.
   function capi_lj_profile(alpha, mu, n, n_profile, profile, a_star, capacity, x_star, &
         traction, gap, state, n_points, message, message_capacity) result(status) &
         bind(C, name="wa_lj_profile")
      !> Johnson's parameter and the transition parameter (the supported domain, mu > 0)
      real(c_double), value, intent(in) :: alpha, mu
      !> Grid points per period: 0 (automatic) or even, >= 8
      integer(c_int), value, intent(in) :: n
      !> Number of profile samples, >= 4 when profile is not NULL (else ignored)
      integer(c_int), value, intent(in) :: n_profile
      !> const double[n_profile] or NULL (the sinusoid): heights over Delta at x* = j/n_profile
      type(c_ptr), value, intent(in) :: profile
      !> The contact half-width wanted, in [0, 1/2]
      real(c_double), value, intent(in) :: a_star
      !> Length of the arrays, >= 0 (the arrays may be NULL when it is 0)
      integer(c_int), value, intent(in) :: capacity
      !> double[capacity]: x*, traction p/p* (compressive positive), gap h/Delta
      type(c_ptr), value, intent(in) :: x_star, traction, gap
      !> double[4] or NULL: a*, b*, P*, gbar* of the state drawn
      type(c_ptr), value, intent(in) :: state
      !> int *: receives N, the number of points
      type(c_ptr), value, intent(in) :: n_points
      !> char * or NULL: receives the message; its size in bytes, NUL included
      type(c_ptr), value, intent(in) :: message
      integer(c_int), value, intent(in) :: message_capacity
      integer(c_int) :: status
      status = lj_profile_core(alpha, mu, n, n_profile, profile, a_star, capacity, &
         [x_star, traction, gap], state, n_points, message, message_capacity)
   end function capi_lj_profile

   ! ---------------------------------------------------------------- cores

   !> Validate, run lj_cycle, write the five values, their errors and N.
   !> values = [P_fc, P_pf, P_snap, W_star, P_fc_peak] (the last may be NULL).
   function lj_cycle_core(alpha, mu, n, n_profile, profile, values, errors, n_used, message, &
         message_capacity) result(status)
      real(c_double), intent(in) :: alpha, mu
      integer(c_int), intent(in) :: n, n_profile, message_capacity
      type(c_ptr), intent(in) :: profile, values(5), errors, n_used, message
      integer(c_int) :: status
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_cycle_type) :: cycle
      real(wp), allocatable :: prof(:)
      integer :: stat, k
      character(len=12) :: text
      character(len=msg_len) :: msg

      msg = ""
      stat = wa_ok
      do k = 1, 5
         call put_nan(values(k))
      end do
      call put_nans(errors, 5_c_int)
      call put_int(n_used, 0)
      if (.not. all([(c_associated(values(k)), k = 1, 4)])) call set_error( &
         wa_invalid_argument, "P_fc, P_pf, P_snap and W_star must not be NULL", stat, msg)
      if (stat == wa_ok .and. n /= 0 .and. (modulo(n, 4_c_int) /= 0 .or. n < 16)) then
         write (text, '(i0)') n
         call set_error(wa_invalid_argument, "n = "//trim(text)//" is outside its valid "// &
            "range: 0 (automatic) or a multiple of 4, >= 16 (the error estimate solves N/2 "// &
            "too)", stat, msg)
      end if
      if (stat == wa_ok) call lj_inputs(alpha, mu, n, n_profile, profile, params, prof, &
         problem, stat, msg)
      if (stat == wa_ok) call lj_cycle(params, cycle, stat, msg, int(n), prof)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         call store_scalar(values(1), cycle%p_fc)
         call store_scalar(values(2), cycle%p_pf)
         call store_scalar(values(3), cycle%p_snap)
         call store_scalar(values(4), cycle%w_star)
         if (c_associated(values(5))) call store_scalar(values(5), cycle%p_fc_peak)
         if (c_associated(errors)) call store_reals(errors, [cycle%p_fc_err, &
            cycle%p_pf_err, cycle%p_snap_err, cycle%w_star_err, cycle%p_fc_peak_err])
         call put_int(n_used, cycle%n_period)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function lj_cycle_core

   !> Validate, trace, write min(n, capacity) points, n and N.
   !> reals = [P_star, gbar, a_star, b_star], ints = [stable_load, stable_gap, event].
   function lj_trace_core(alpha, mu, n, n_profile, profile, capacity, reals, ints, n_points, &
         n_used, message, message_capacity) result(status)
      real(c_double), intent(in) :: alpha, mu
      integer(c_int), intent(in) :: n, n_profile, capacity, message_capacity
      type(c_ptr), intent(in) :: profile, reals(4), ints(3), n_points, n_used, message
      integer(c_int) :: status
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: branch
      real(wp), allocatable :: prof(:)
      integer(c_int), pointer :: n_out
      integer :: stat, m
      character(len=msg_len) :: msg

      msg = ""
      call put_int(n_points, 0)
      call put_int(n_used, 0)
      call check_outputs("n_points", n_points, "capacity", capacity, reals, &
         "P_star, gbar, a_star and b_star", stat, msg)
      if (stat == wa_ok) call lj_inputs(alpha, mu, n, n_profile, profile, params, prof, &
         problem, stat, msg)
      if (stat == wa_ok) call lj_trace(problem, branch, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         m = min(branch%n, int(capacity))
         call store_reals(reals(1), branch%p_star(1:m))
         call store_reals(reals(2), branch%gbar(1:m))
         call store_reals(reals(3), branch%a_star(1:m))
         call store_reals(reals(4), branch%b_star(1:m))
         if (c_associated(ints(1))) call store_ints(ints(1), &
            merge(1, 0, branch%stable_load(1:m)))
         if (c_associated(ints(2))) call store_ints(ints(2), &
            merge(1, 0, branch%stable_gap(1:m)))
         if (c_associated(ints(3))) call store_ints(ints(3), branch%event(1:m))
         call c_f_pointer(n_points, n_out)
         n_out = int(branch%n, c_int)
         call put_int(n_used, branch%n_period)
         if (branch%n > capacity) call too_small("the curve has", "points", branch%n, &
            capacity, stat, msg)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function lj_trace_core

   !> Validate, draw the state (lj_state_at_a), write min(N, capacity) points, the state
   !> and N. reals = [x_star, traction, gap].
   function lj_profile_core(alpha, mu, n, n_profile, profile, a_star, capacity, reals, &
         state, n_points, message, message_capacity) result(status)
      real(c_double), intent(in) :: alpha, mu, a_star
      integer(c_int), intent(in) :: n, n_profile, capacity, message_capacity
      type(c_ptr), intent(in) :: profile, reals(3), state, n_points, message
      integer(c_int) :: status
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(lj_state_type) :: drawn
      real(wp), allocatable :: prof(:)
      integer :: stat, m
      character(len=msg_len) :: msg

      msg = ""
      call put_int(n_points, 0)
      call put_nans(state, 4_c_int)
      call check_outputs("n_points", n_points, "capacity", capacity, reals, &
         "x_star, traction and gap", stat, msg)
      if (stat == wa_ok) call lj_inputs(alpha, mu, n, n_profile, profile, params, prof, &
         problem, stat, msg)
      if (stat == wa_ok) call lj_state_at_a(problem, real(a_star, wp), drawn, stat, msg)
      call internal_capacity(stat, msg)
      if (stat == wa_ok) then
         m = min(drawn%n_period, int(capacity))
         call store_reals(reals(1), drawn%x(1:m))
         call store_reals(reals(2), drawn%traction(1:m))
         call store_reals(reals(3), drawn%gap(1:m))
         if (c_associated(state)) call store_reals(state, [drawn%a_star, drawn%b_star, &
            drawn%p_star, drawn%gbar])
         call put_int(n_points, drawn%n_period)
         if (drawn%n_period > capacity) call too_small("the profile has", "points", &
            drawn%n_period, capacity, stat, msg)
      end if
      status = int(stat, c_int)
      call copy_message(status, msg, message, message_capacity)
   end function lj_profile_core

   !> The checks the exports share: the profile's count, alpha and mu, then the problem
   !> itself (lj_problem: n, the profile's values, mu > 0, the grid's caps; a cap
   !> exceeded is the caller's n or parameters, so WA_INVALID_ARGUMENT). prof receives a
   !> copy of the samples (left unallocated, i.e. absent, for the sinusoid).
   subroutine lj_inputs(alpha, mu, n, n_profile, profile, params, prof, problem, stat, msg)
      real(c_double), intent(in) :: alpha, mu
      integer(c_int), intent(in) :: n, n_profile
      type(c_ptr), intent(in) :: profile
      type(params_type), intent(out) :: params
      real(wp), allocatable, intent(out) :: prof(:)
      type(lj_problem_type), intent(out) :: problem
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      real(c_double), pointer :: samples(:)
      character(len=12) :: text

      stat = wa_ok
      if (c_associated(profile)) then
         if (n_profile < 4) then
            write (text, '(i0)') n_profile
            call set_error(wa_invalid_argument, "n_profile = "//trim(text)// &
               " is outside its valid range [4, inf) (profile is not NULL)", stat, msg)
            return
         end if
         call c_f_pointer(profile, samples, [n_profile])
         ! a sample not finite would reach the resampling and the solver (a crash)
         if (.not. all(ieee_is_finite(samples))) then
            write (text, '(i0)') findloc(ieee_is_finite(samples), .false., dim=1) - 1
            call set_error(wa_invalid_argument, "profile["//trim(text)//"] is not a "// &
               "finite number", stat, msg)
            return
         end if
         prof = samples
      end if
      call new_params(alpha, mu, params, stat, msg)
      if (stat /= wa_ok) return
      call lj_problem(params, problem, stat, msg, int(n), prof)
      if (stat == wa_capacity_too_small) stat = wa_invalid_argument
   end subroutine lj_inputs

end module wa_capi_lj
