!> Flat f2py facade of the wavyadhesion library (compiled into the extension module
!> `wavyadhesion._wa_f2py`; the Python layer in wavyadhesion/_core.py is the public face).
!>
!> f2py rules kept here: external subroutines only (no module procedures, no
!> `value`), kinds from iso_c_binding in every signature (a kind imported from our own
!> modules would be mapped to C float), explicit-shape arrays sized by leading
!> arguments, and `status` plus `character(len=256) :: message` last. Each call loops
!> over a whole numpy array in Fortran and releases the GIL (`!f2py threadsafe`).
!>
!> Array routines process every point: a failed point gets NaN (zone case 0) and the
!> first failure is reported through `ifail` (1-based index, 0 if none), `status` and
!> `message`; `nfail` counts the failures.

!> Switch GSL's abort-on-error handler off (a host Python process must not abort).
subroutine fa_init()
   use, intrinsic :: iso_c_binding, only: c_funptr
   use wa_gsl, only: gsl_set_error_handler_off
   implicit none
   type(c_funptr) :: previous
   previous = gsl_set_error_handler_off()
end subroutine fa_init

!> Short fixed text of a status code (wa_status::status_message).
subroutine fa_status_text(code, message)
   use, intrinsic :: iso_c_binding, only: c_int
   use wa_status, only: status_message
   implicit none
   !> A status code
   integer(c_int), intent(in) :: code
   !> Its text
   character(len=256), intent(out) :: message
   message = status_message(int(code))
end subroutine fa_status_text

!> The library's bounds on arguments, so that the Python layer checks the same ones
!> before it allocates anything: the (alpha, mu) domain (wa_params) and the size of an
!> adhesion map's grid (wa_map).
subroutine fa_limits(alpha_min, alpha_max, mu_min, mu_max, map_n_mu_max, map_n_alpha_max, &
      map_cells_max)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_params, only: p_alpha_min => alpha_min, p_alpha_max => alpha_max, &
      p_mu_min => mu_min, p_mu_max => mu_max
   use wa_map, only: p_n_mu_max => map_n_mu_max, p_n_alpha_max => map_n_alpha_max, &
      p_cells_max => map_cells_max
   implicit none
   !> alpha in [alpha_min, alpha_max]; mu = 0 or in [mu_min, mu_max]
   real(c_double), intent(out) :: alpha_min, alpha_max, mu_min, mu_max
   !> adhesion_map: n_mu in [2, map_n_mu_max], at most map_n_alpha_max alpha values and
   !> map_cells_max cells n_mu*n_alpha
   integer(c_int), intent(out) :: map_n_mu_max, map_n_alpha_max, map_cells_max
   alpha_min = p_alpha_min; alpha_max = p_alpha_max
   mu_min = p_mu_min; mu_max = p_mu_max
   map_n_mu_max = int(p_n_mu_max, c_int)
   map_n_alpha_max = int(p_n_alpha_max, c_int)
   map_cells_max = int(p_cells_max, c_int)
end subroutine fa_limits

!> Westergaard load P* = sin^2(pi a*) at n points   (3.1)
subroutine fa_westergaard_load(n, a_star, p_star, nfail, ifail, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_validate, only: check_range
   use wa_kernels, only: westergaard_load
   implicit none
   !> Number of points
   integer(c_int), intent(in) :: n
   !> Contact half-widths over the period, in [0, 1/2]
   real(c_double), intent(in) :: a_star(n)
   !> Loads P*
   real(c_double), intent(out) :: p_star(n)
   !> Number of invalid points
   integer(c_int), intent(out) :: nfail
   !> Index of the first invalid point (1-based, 0 if none)
   integer(c_int), intent(out) :: ifail
   !> wa_ok or the first failure's status
   integer(c_int), intent(out) :: status
   !> The first failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   character(len=256) :: msg
   integer :: i, stat

   nfail = 0; ifail = 0; status = wa_ok; message = ""
   do i = 1, n
      call check_range("a_star", a_star(i), 0.0_c_double, 0.5_c_double, "[0, 1/2]", stat, msg)
      if (stat == wa_ok) then
         p_star(i) = westergaard_load(a_star(i))
      else
         p_star(i) = ieee_value(p_star(i), ieee_quiet_nan)
         nfail = nfail + 1
         if (ifail == 0) then
            ifail = i; status = stat; message = msg
         end if
      end if
   end do
end subroutine fa_westergaard_load

!> JKR load P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)) at n points   (3.4)
subroutine fa_jkr_load(n, alpha, a_star, p_star, nfail, ifail, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_validate, only: check_range
   use wa_kernels, only: jkr_load
   implicit none
   !> Number of points
   integer(c_int), intent(in) :: n
   !> Johnson's parameter, >= 0
   real(c_double), intent(in) :: alpha(n)
   !> Contact half-widths over the period, in [0, 1/2]
   real(c_double), intent(in) :: a_star(n)
   !> Loads P* (-Infinity at a* = 1/2)
   real(c_double), intent(out) :: p_star(n)
   !> Number of invalid points
   integer(c_int), intent(out) :: nfail
   !> Index of the first invalid point (1-based, 0 if none)
   integer(c_int), intent(out) :: ifail
   !> wa_ok or the first failure's status
   integer(c_int), intent(out) :: status
   !> The first failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   character(len=256) :: msg
   integer :: i, stat

   nfail = 0; ifail = 0; status = wa_ok; message = ""
   do i = 1, n
      call check_range("alpha", alpha(i), 0.0_c_double, huge(1.0_c_double), "[0, inf)", &
         stat, msg, hi_open=.true.)
      if (stat == wa_ok) call check_range("a_star", a_star(i), 0.0_c_double, 0.5_c_double, &
         "[0, 1/2]", stat, msg)
      if (stat == wa_ok) then
         p_star(i) = jkr_load(alpha(i), a_star(i))
      else
         p_star(i) = ieee_value(p_star(i), ieee_quiet_nan)
         nfail = nfail + 1
         if (ifail == 0) then
            ifail = i; status = stat; message = msg
         end if
      end if
   end do
end subroutine fa_jkr_load

!> Principal equilibrium of `model` at n points (alpha, mu, a*), broadcast by the caller.
subroutine fa_equilibrium(n, model, alpha, mu, a_star, c_star, p_star, zone_case, gbar, &
      nfail, ifail, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_models, only: check_model, model_equilibrium
   implicit none
   !> Number of points
   integer(c_int), intent(in) :: n
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha(n)
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu(n)
   !> Contact half-widths over the period, in [0, 1/2]
   real(c_double), intent(in) :: a_star(n)
   !> Interaction-zone half-widths c*
   real(c_double), intent(out) :: c_star(n)
   !> Loads P*
   real(c_double), intent(out) :: p_star(n)
   !> Zone cases (1, 2, 3; 0 where the point failed)
   integer(c_int), intent(out) :: zone_case(n)
   !> Mean gaps gbar* (NaN where the point failed or the mean gap is not defined)
   real(c_double), intent(out) :: gbar(n)
   !> Number of failed points
   integer(c_int), intent(out) :: nfail
   !> Index of the first failed point (1-based, 0 if none)
   integer(c_int), intent(out) :: ifail
   !> wa_ok or the first failure's status
   integer(c_int), intent(out) :: status
   !> The first failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(state_type) :: state
   character(len=256) :: msg
   integer :: i, stat, stat_params

   nfail = 0; ifail = 0; status = wa_ok; message = ""
   call check_model(int(model), stat, message)
   if (stat /= wa_ok) then
      nfail = n; ifail = 1; status = stat
      c_star = ieee_value(1.0_c_double, ieee_quiet_nan); p_star = c_star; zone_case = 0
      gbar = c_star
      return
   end if
   stat_params = -1
   do i = 1, n
      msg = ""
      ! new parameters only where (alpha, mu) change: usually once per array
      if (i == 1 .or. stat_params /= wa_ok) then
         call new_params(alpha(i), mu(i), params, stat_params, msg)
      else if (alpha(i) /= alpha(i - 1) .or. mu(i) /= mu(i - 1)) then
         call new_params(alpha(i), mu(i), params, stat_params, msg)
      end if
      stat = stat_params
      if (stat == wa_ok) call model_equilibrium(int(model), params, a_star(i), state, stat, msg)
      if (stat == wa_ok) then
         c_star(i) = state%c_star
         p_star(i) = state%p_star
         zone_case(i) = int(state%zone_case, c_int)
         gbar(i) = state%gbar
         if (.not. (state%gbar >= 0.0_c_double .and. state%gbar <= huge(1.0_c_double))) &
            gbar(i) = ieee_value(gbar(i), ieee_quiet_nan)
      else
         c_star(i) = ieee_value(c_star(i), ieee_quiet_nan)
         p_star(i) = c_star(i)
         zone_case(i) = 0
         gbar(i) = c_star(i)
         nfail = nfail + 1
         if (ifail == 0) then
            ifail = i; status = stat; message = msg
         end if
      end if
   end do
end subroutine fa_equilibrium

!> Every equilibrium of `model` at one point: the first min(n_roots, capacity) states;
!> status 4 (capacity too small) when n_roots > capacity.
subroutine fa_roots(capacity, model, alpha, mu, a_star, c_star, p_star, zone_case, &
      gap_width, gbar, n_roots, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_models, only: model_roots
   implicit none
   !> Length of the output arrays, >= 1
   integer(c_int), intent(in) :: capacity
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> Contact half-width over the period, in [0, 1/2]
   real(c_double), intent(in) :: a_star
   !> c* of each state
   real(c_double), intent(out) :: c_star(capacity)
   !> P* of each state
   real(c_double), intent(out) :: p_star(capacity)
   !> Zone case of each state
   integer(c_int), intent(out) :: zone_case(capacity)
   !> c* - a* of each state (accurate where the zone is very thin)
   real(c_double), intent(out) :: gap_width(capacity)
   !> Mean gap gbar* of each state (NaN where not defined)
   real(c_double), intent(out) :: gbar(capacity)
   !> Number of states (may exceed capacity)
   integer(c_int), intent(out) :: n_roots
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(state_type) :: states(capacity)
   integer :: k, n, stat

   message = ""
   c_star = 0.0_c_double; p_star = 0.0_c_double; zone_case = 0; gap_width = 0.0_c_double
   gbar = 0.0_c_double
   n = 0
   call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call model_roots(int(model), params, a_star, states, n, stat, message)
   if (stat == wa_ok .or. stat == wa_capacity_too_small) then
      do k = 1, min(n, int(capacity))
         c_star(k) = states(k)%c_star
         p_star(k) = states(k)%p_star
         zone_case(k) = int(states(k)%zone_case, c_int)
         gap_width(k) = states(k)%gap_width
         gbar(k) = states(k)%gbar
         if (.not. (states(k)%gbar >= 0.0_c_double .and. states(k)%gbar <= huge(1.0_c_double))) &
            gbar(k) = ieee_value(gbar(k), ieee_quiet_nan)
      end do
   else
      n = 0
   end if
   n_roots = int(n, c_int)
   status = int(stat, c_int)
end subroutine fa_roots

!> Validated parameters and what derives from them: Sigma0 and Dcod.
subroutine fa_params(alpha, mu, sigma0, dcod, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_params, only: params_type, new_params
   implicit none
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> Peak adhesive stress over p*
   real(c_double), intent(out) :: sigma0
   !> Maugis-Dugdale opening (+Infinity at mu = 0)
   real(c_double), intent(out) :: dcod
   !> wa_ok or wa_invalid_argument
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   integer :: stat

   message = ""
   call new_params(alpha, mu, params, stat, message)
   sigma0 = params%sigma0
   dcod = params%dcod
   status = int(stat, c_int)
end subroutine fa_params

!> Reduced modulus 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2   (2.2b)
subroutine fa_reduced_modulus(e1, nu1, e2, nu2, estar, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_params, only: reduced_modulus
   implicit none
   !> Young's modulus of body 1 [Pa]
   real(c_double), intent(in) :: e1
   !> Poisson's ratio of body 1
   real(c_double), intent(in) :: nu1
   !> Young's modulus of body 2 [Pa]
   real(c_double), intent(in) :: e2
   !> Poisson's ratio of body 2
   real(c_double), intent(in) :: nu2
   !> Reduced modulus [Pa]
   real(c_double), intent(out) :: estar
   !> wa_ok or wa_invalid_argument
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   integer :: stat

   message = ""
   call reduced_modulus(e1, nu1, e2, nu2, estar, stat, message)
   status = int(stat, c_int)
end subroutine fa_reduced_modulus

!> alpha, mu, Sigma0, Dcod and the SI scales from E*, L, Delta, dgamma, sigma0 (doc/theory.md, "Parameters").
subroutine fa_dimensional(estar, period, amplitude, work_of_adhesion, peak_stress, alpha, &
      mu, sigma0, dcod, pressure, force, length, radius, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_params, only: params_type, scales_type, dimensional_params
   implicit none
   !> Reduced modulus [Pa]
   real(c_double), intent(in) :: estar
   !> Period L [m]
   real(c_double), intent(in) :: period
   !> Amplitude Delta [m]
   real(c_double), intent(in) :: amplitude
   !> Work of adhesion [J/m^2]
   real(c_double), intent(in) :: work_of_adhesion
   !> Peak adhesive stress [Pa]
   real(c_double), intent(in) :: peak_stress
   !> Johnson's parameter
   real(c_double), intent(out) :: alpha
   !> Transition parameter
   real(c_double), intent(out) :: mu
   !> Peak adhesive stress over p*
   real(c_double), intent(out) :: sigma0
   !> Maugis-Dugdale opening
   real(c_double), intent(out) :: dcod
   !> p* = pi E* Delta / L [Pa]
   real(c_double), intent(out) :: pressure
   !> p* L [N/m]
   real(c_double), intent(out) :: force
   !> L [m]
   real(c_double), intent(out) :: length
   !> Crest radius R = L^2/(4 pi^2 Delta) [m]
   real(c_double), intent(out) :: radius
   !> wa_ok or wa_invalid_argument
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(scales_type) :: scales
   integer :: stat

   message = ""
   call dimensional_params(estar, period, amplitude, work_of_adhesion, peak_stress, &
      params, scales, stat, message)
   alpha = params%alpha; mu = params%mu; sigma0 = params%sigma0; dcod = params%dcod
   pressure = scales%pressure; force = scales%force; length = scales%length
   radius = scales%radius
   status = int(stat, c_int)
end subroutine fa_dimensional

!> The equilibrium branch of `model` by continuation: the first min(n_points, capacity)
!> points, in the order of the curve; status 4 (capacity too small) when n_points >
!> capacity (call again with capacity >= n_points). On other failures n_points = 0.
subroutine fa_trace_branch(capacity, model, alpha, mu, a_star, c_star, p_star, b_star, &
      zone_case, stable, event, extremum, gbar, n_points, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_branch, only: branch_type, trace_branch
   implicit none
   !> Length of the output arrays, >= 1
   integer(c_int), intent(in) :: capacity
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> a* of each point
   real(c_double), intent(out) :: a_star(capacity)
   !> c* of each point
   real(c_double), intent(out) :: c_star(capacity)
   !> P* of each point
   real(c_double), intent(out) :: p_star(capacity)
   !> b* = a* + 0.4 (c* - a*) of each point (the command line's b_star column)
   real(c_double), intent(out) :: b_star(capacity)
   !> Zone case of each point
   integer(c_int), intent(out) :: zone_case(capacity)
   !> 1 where dP*/da* > 0 (stable under load control), else 0
   integer(c_int), intent(out) :: stable(capacity)
   !> Event code of each point (0 none, 1 fold, 2 zone-case switch, 8 branch end, 9 a*-turn)
   integer(c_int), intent(out) :: event(capacity)
   !> +1 local maximum of P* along the curve, -1 local minimum, 0 otherwise
   integer(c_int), intent(out) :: extremum(capacity)
   !> Mean gap gbar* of each point (NaN where not defined)
   real(c_double), intent(out) :: gbar(capacity)
   !> Number of points (may exceed capacity)
   integer(c_int), intent(out) :: n_points
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(branch_type) :: branch
   integer :: m, stat

   message = ""
   a_star = 0.0_c_double; c_star = 0.0_c_double; p_star = 0.0_c_double
   b_star = 0.0_c_double; zone_case = 0; stable = 0; event = 0; extremum = 0
   gbar = 0.0_c_double
   n_points = 0
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call trace_branch(int(model), params, branch, stat, message)
   if (stat == wa_ok) then
      m = min(branch%n, int(capacity))
      a_star(1:m) = branch%a_star(1:m)
      c_star(1:m) = branch%c_star(1:m)
      p_star(1:m) = branch%p_star(1:m)
      b_star(1:m) = branch%a_star(1:m) + 0.4_c_double*(branch%c_star(1:m) - branch%a_star(1:m))
      zone_case(1:m) = int(branch%zone_case(1:m), c_int)
      stable(1:m) = merge(1_c_int, 0_c_int, branch%stable(1:m))
      event(1:m) = int(branch%event(1:m), c_int)
      extremum(1:m) = int(branch%extremum(1:m), c_int)
      gbar(1:m) = branch%gbar(1:m)
      where (.not. (gbar(1:m) >= 0.0_c_double .and. gbar(1:m) <= huge(1.0_c_double))) &
         gbar(1:m) = ieee_value(1.0_c_double, ieee_quiet_nan)
      n_points = int(branch%n, c_int)
      if (branch%n > capacity) then
         stat = wa_capacity_too_small
         message = "fa_trace_branch: capacity too small"
      end if
   end if
   status = int(stat, c_int)
end subroutine fa_trace_branch

!> The events of load-controlled loading (stage 1) and unloading (stage 2), P_fc*, P_pf*,
!> their mechanisms and the loop area: the first min(n_events, capacity) events; status 4
!> when n_events > capacity. On other failures n_events = 0 and P_fc = P_pf = NaN.
subroutine fa_load_path(capacity, model, alpha, mu, stage, event, a_star, c_star, p_star, &
      n_events, p_fc, p_pf, fc_mechanism, pf_mechanism, loop_area, jump_energy, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_loadpath, only: path_type, path_from_branch
   use wa_branch, only: branch_type, trace_branch
   use wa_jump_energy, only: load_jump_energies
   implicit none
   !> Length of the event arrays, >= 1
   integer(c_int), intent(in) :: capacity
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> Stage of each event: 1 loading, 2 unloading
   integer(c_int), intent(out) :: stage(capacity)
   !> Event code of each event (3 jump start, 4 jump end, 5 full contact reached, ...)
   integer(c_int), intent(out) :: event(capacity)
   !> a* of each event
   real(c_double), intent(out) :: a_star(capacity)
   !> c* of each event
   real(c_double), intent(out) :: c_star(capacity)
   !> P* of each event
   real(c_double), intent(out) :: p_star(capacity)
   !> Number of events (may exceed capacity)
   integer(c_int), intent(out) :: n_events
   !> Load at which full contact is first reached
   real(c_double), intent(out) :: p_fc
   !> Pull-off load (-Infinity: never)
   real(c_double), intent(out) :: p_pf
   !> How full contact is reached: 0 gradual, 1 jump (case 1), 2 jump (case 2), 3 snap
   integer(c_int), intent(out) :: fc_mechanism
   !> How contact is lost: 0 gradual, 1 jump (case 1), 2 jump (case 2)
   integer(c_int), intent(out) :: pf_mechanism
   !> Area of the P*-a* hysteresis loop
   real(c_double), intent(out) :: loop_area
   !> Energy released by the jump starting at each event (NaN at other events)
   real(c_double), intent(out) :: jump_energy(capacity)
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(path_type) :: path
   type(branch_type) :: branch
   real(c_double) :: energy(64)
   integer :: m, stat

   message = ""
   stage = 0; event = 0; a_star = 0.0_c_double; c_star = 0.0_c_double; p_star = 0.0_c_double
   n_events = 0; fc_mechanism = -1; pf_mechanism = -1
   p_fc = ieee_value(1.0_c_double, ieee_quiet_nan); p_pf = p_fc; loop_area = p_fc
   jump_energy = p_fc
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call trace_branch(int(model), params, branch, stat, message)
   if (stat == wa_ok) call path_from_branch(int(model), params, branch, path, stat, message)
   if (stat == wa_ok) call load_jump_energies(int(model), params, branch, path, energy, stat, &
      message)
   if (stat == wa_ok) then
      m = min(path%n, int(capacity))
      stage(1:m) = int(path%stage(1:m), c_int)
      event(1:m) = int(path%event(1:m), c_int)
      a_star(1:m) = path%a_star(1:m)
      c_star(1:m) = path%c_star(1:m)
      p_star(1:m) = path%p_star(1:m)
      n_events = int(path%n, c_int)
      p_fc = path%p_fc; p_pf = path%p_pf
      fc_mechanism = int(path%fc_mechanism, c_int)
      pf_mechanism = int(path%pf_mechanism, c_int)
      loop_area = path%loop_area
      jump_energy(1:m) = energy(1:m)
      if (path%n > capacity) then
         stat = wa_capacity_too_small
         message = "fa_load_path: capacity too small"
      end if
   end if
   status = int(stat, c_int)
end subroutine fa_load_path

!> P_fc*, P_pf* and their mechanisms for one alpha over n values of mu, in one call of
!> wa_loadpath::critical_sweep. Every mu is validated first: the first invalid one is
!> reported through ifail (1-based), nothing is computed and every output is NaN
!> (mechanisms -1). A mu whose load path fails gets NaN (-1) in its own row and its
!> status in row_status; every other row is computed, and status/message are those of
!> the first failing row.
subroutine fa_critical_sweep(n, model, alpha, mu, p_fc, p_pf, fc_mechanism, pf_mechanism, &
      row_status, ifail, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_loadpath, only: critical_sweep
   implicit none
   !> Number of mu values
   integer(c_int), intent(in) :: n
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameters, >= 0
   real(c_double), intent(in) :: mu(n)
   !> Loads at which full contact is first reached
   real(c_double), intent(out) :: p_fc(n)
   !> Pull-off loads (-Infinity: never)
   real(c_double), intent(out) :: p_pf(n)
   !> How full contact is reached (0 gradual, 1 jump case 1, 2 jump case 2, 3 snap)
   integer(c_int), intent(out) :: fc_mechanism(n)
   !> How contact is lost (0 gradual, 1 jump case 1, 2 jump case 2)
   integer(c_int), intent(out) :: pf_mechanism(n)
   !> Status of each row (wa_ok where its forces were computed)
   integer(c_int), intent(out) :: row_status(n)
   !> Index of the invalid mu (1-based), 0 when every mu is valid
   integer(c_int), intent(out) :: ifail
   !> wa_ok or the first failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   integer, allocatable :: fc_mech(:), pf_mech(:), row_stat(:)
   integer :: i, stat

   message = ""
   ifail = 0
   p_fc = ieee_value(1.0_c_double, ieee_quiet_nan); p_pf = p_fc
   fc_mechanism = -1; pf_mechanism = -1
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, 0.0_c_double, params, stat, message)
   do i = 1, n
      if (stat /= wa_ok) exit
      call new_params(alpha, mu(i), params, stat, message)
      if (stat /= wa_ok) ifail = i
   end do
   row_status = int(stat, c_int)
   if (stat == wa_ok .and. n > 0) then
      allocate (fc_mech(n), pf_mech(n), row_stat(n))
      call critical_sweep(int(model), alpha, mu, p_fc, p_pf, fc_mech, pf_mech, stat, message, &
         row_stat)
      fc_mechanism = int(fc_mech, c_int)
      pf_mechanism = int(pf_mech, c_int)
      row_status = int(row_stat, c_int)
   end if
   status = int(stat, c_int)
end subroutine fa_critical_sweep

!> The adhesion map (wa_map's adhesion_map): the boundary points flattened curve after
!> curve (code, alpha, mu, curve index from 1, start/end kinds per point's curve) and the
!> region grids. n_out may exceed capacity (then status = wa_capacity_too_small and only
!> capacity points are written).
subroutine fa_adhesion_map(n_alpha, n_mu, capacity, model, alpha, mu_lo, mu_hi, scan_every, &
      control, code, alpha_out, mu_out, curve, end_kinds, n_out, mu_grid, fc_region, &
      pf_region, ga_region, gr_region, n_paths, status, message, special_kind, &
      special_codes, special_point, n_special)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_map, only: map_type, adhesion_map
   implicit none
   !> Number of alpha values, >= 1
   integer(c_int), intent(in) :: n_alpha
   !> Number of log-spaced mu values of the region grid, >= 2
   integer(c_int), intent(in) :: n_mu
   !> Length of the point outputs
   integer(c_int), intent(in) :: capacity
   !> Model constant: 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Strictly increasing alpha values
   real(c_double), intent(in) :: alpha(n_alpha)
   !> The mu range
   real(c_double), intent(in) :: mu_lo, mu_hi
   !> The discovery scan runs at every scan_every-th alpha
   integer(c_int), intent(in) :: scan_every
   !> wa_map's map_control_*: 1 load, 2 gap, 3 both
   integer(c_int), intent(in) :: control
   !> Boundary code, alpha, mu and curve index (from 1) of each point
   integer(c_int), intent(out) :: code(capacity)
   real(c_double), intent(out) :: alpha_out(capacity), mu_out(capacity)
   integer(c_int), intent(out) :: curve(capacity)
   !> Start and end kind of each point's curve
   integer(c_int), intent(out) :: end_kinds(2, capacity)
   !> Number of points (may exceed capacity)
   integer(c_int), intent(out) :: n_out
   !> The mu grid and the mechanisms at (mu, alpha)
   real(c_double), intent(out) :: mu_grid(n_mu)
   integer(c_int), intent(out) :: fc_region(n_mu, n_alpha), pf_region(n_mu, n_alpha)
   !> Gap-control approach and retraction mechanisms at (mu, alpha) (-1 without control 2)
   integer(c_int), intent(out) :: ga_region(n_mu, n_alpha), gr_region(n_mu, n_alpha)
   !> Load paths computed
   integer(c_int), intent(out) :: n_paths
   integer(c_int), intent(out) :: status
   character(len=256), intent(out) :: message
   !> Special points (wa_map::map_point, at most 128): kind, the boundary codes involved
   !> (second 0 if one), alpha and mu; n_special of them
   integer(c_int), intent(out) :: special_kind(128), special_codes(2, 128)
   real(c_double), intent(out) :: special_point(2, 128)
   integer(c_int), intent(out) :: n_special
   !f2py threadsafe
   type(map_type) :: map
   integer :: c, p, n, stat

   message = ""
   code = 0; alpha_out = 0; mu_out = 0; curve = 0; end_kinds = 0; mu_grid = 0
   fc_region = -1; pf_region = -1; ga_region = -1; gr_region = -1; n_paths = 0
   special_kind = 0; special_codes = 0; special_point = 0; n_special = 0
   n = 0
   call adhesion_map(int(model), alpha, mu_lo, mu_hi, int(n_mu), map, stat, message, &
      scan_every=int(scan_every), control=int(control))
   if (stat == wa_ok) then
      mu_grid = map%mu
      fc_region = map%fc_region
      pf_region = map%pf_region
      ga_region = map%ga_region
      gr_region = map%gr_region
      n_paths = map%n_paths
      n_special = int(min(map%n_special, 128), c_int)
      do c = 1, n_special
         special_kind(c) = map%special(c)%kind
         special_codes(:, c) = map%special(c)%codes
         special_point(:, c) = [map%special(c)%alpha, map%special(c)%mu]
      end do
      do c = 1, map%n_boundaries
         do p = 1, map%boundary(c)%n
            n = n + 1
            if (n > capacity) cycle
            code(n) = map%boundary(c)%code
            alpha_out(n) = map%boundary(c)%alpha(p)
            mu_out(n) = map%boundary(c)%mu(p)
            curve(n) = c
            end_kinds(:, n) = [map%boundary(c)%start_kind, map%boundary(c)%end_kind]
         end do
      end do
      if (n > capacity) then
         stat = wa_capacity_too_small
         message = "adhesion_map: more boundary points than capacity"
      end if
   end if
   n_out = int(n, c_int)
   status = int(stat, c_int)
end subroutine fa_adhesion_map
!> Traction p/p* and gap h/Delta at n points x* of one state (wa_models::model_profile):
!> the one at a* with c* nearest c_star (within 1e-6), or the principal state when
!> principal /= 0; also the state (a*, c*, P*, zone case, gbar). On failure status /= 0,
!> traction = gap = NaN.
subroutine fa_profile(n, model, alpha, mu, a_star, c_star, principal, x_star, traction, gap, &
      state_c, state_p, state_zone, state_gbar, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_models, only: check_model, model_profile
   implicit none
   !> Number of points
   integer(c_int), intent(in) :: n
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> Contact half-width over the period, in [0, 1/2]
   real(c_double), intent(in) :: a_star
   !> Interaction-zone half-width of the state, in [0, 1/2] (ignored when principal /= 0)
   real(c_double), intent(in) :: c_star
   !> 1: the principal state at a*, 0: the state with c* nearest c_star
   integer(c_int), intent(in) :: principal
   !> The points x* (any finite values; period 1, crest at 0)
   real(c_double), intent(in) :: x_star(n)
   !> p/p* at each point
   real(c_double), intent(out) :: traction(n)
   !> h/Delta at each point
   real(c_double), intent(out) :: gap(n)
   !> c*, P*, zone case and gbar* of the state
   real(c_double), intent(out) :: state_c, state_p, state_gbar
   integer(c_int), intent(out) :: state_zone
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(state_type) :: state
   integer :: stat

   message = ""
   state_c = ieee_value(1.0_c_double, ieee_quiet_nan)
   state_p = state_c; state_gbar = state_c; state_zone = -1
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) then
      if (principal /= 0) then
         call model_profile(int(model), params, a_star, x_star, traction, gap, state, stat, &
            message)
      else
         call model_profile(int(model), params, a_star, x_star, traction, gap, state, stat, &
            message, c_star)
      end if
   end if
   if (stat == wa_ok) then
      state_c = state%c_star
      state_p = state%p_star
      state_zone = int(state%zone_case, c_int)
      state_gbar = state%gbar
   else
      traction = ieee_value(1.0_c_double, ieee_quiet_nan)
      gap = traction
   end if
   status = int(stat, c_int)
end subroutine fa_profile

!> Gap control: P* on approach and retraction and dP*/dgbar* at n mean gaps (gap_law),
!> and the energy lost per cycle W* and W*/(pi alpha^2/2) (gap_path). On failure the
!> arrays and W* are NaN.
subroutine fa_gap_law(n, model, alpha, mu, gbar, p_approach, p_retract, dpdg_approach, &
      dpdg_retract, w_star, w_fraction, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_gappath, only: gap_law
   implicit none
   !> Number of mean gaps, >= 1
   integer(c_int), intent(in) :: n
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> Mean gaps gbar* >= 0
   real(c_double), intent(in) :: gbar(n)
   !> P* on approach and on retraction
   real(c_double), intent(out) :: p_approach(n), p_retract(n)
   !> dP*/dgbar* on approach and on retraction
   real(c_double), intent(out) :: dpdg_approach(n), dpdg_retract(n)
   !> Energy lost per cycle and its fraction of the work of adhesion
   real(c_double), intent(out) :: w_star, w_fraction
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   real(c_double) :: w, wf
   integer :: stat

   message = ""
   w_star = ieee_value(1.0_c_double, ieee_quiet_nan); w_fraction = w_star
   p_approach = w_star; p_retract = w_star; dpdg_approach = w_star; dpdg_retract = w_star
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call gap_law(int(model), params, gbar, p_approach, p_retract, &
      dpdg_approach, dpdg_retract, stat, message, w_star=w, w_fraction=wf)
   if (stat == wa_ok) then
      w_star = w
      w_fraction = wf
   else
      w_star = ieee_value(1.0_c_double, ieee_quiet_nan); w_fraction = w_star
      p_approach = w_star; p_retract = w_star; dpdg_approach = w_star; dpdg_retract = w_star
   end if
   status = int(stat, c_int)
end subroutine fa_gap_law

!> The events of one approach-retraction cycle under gap control (wa_gappath::gap_path)
!> and the energy lost per cycle. capacity too small: status wa_capacity_too_small with
!> n_events the number needed.
subroutine fa_gap_path(capacity, model, alpha, mu, stage, event, zone_case, a_star, c_star, &
      p_star, gbar, n_events, w_star, w_fraction, g_touch, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_gappath, only: gap_path_type, gap_path
   implicit none
   !> Length of the event arrays, >= 1
   integer(c_int), intent(in) :: capacity
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, >= 0
   real(c_double), intent(in) :: mu
   !> Stage (1 approach, 2 retraction), event code and zone case of each event
   integer(c_int), intent(out) :: stage(capacity), event(capacity), zone_case(capacity)
   !> The state at each event
   real(c_double), intent(out) :: a_star(capacity), c_star(capacity), p_star(capacity), &
      gbar(capacity)
   !> Number of events (may exceed capacity)
   integer(c_int), intent(out) :: n_events
   !> Energy lost per cycle, its fraction of the work of adhesion, gbar* of first interaction
   real(c_double), intent(out) :: w_star, w_fraction, g_touch
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(gap_path_type) :: path
   integer :: m, stat

   message = ""
   stage = 0; event = 0; zone_case = 0; n_events = 0
   w_star = ieee_value(1.0_c_double, ieee_quiet_nan); w_fraction = w_star; g_touch = w_star
   a_star = w_star; c_star = w_star; p_star = w_star; gbar = w_star
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call gap_path(int(model), params, path, stat, message)
   if (stat == wa_ok) then
      m = min(path%n, int(capacity))
      stage(1:m) = int(path%stage(1:m), c_int)
      event(1:m) = int(path%event(1:m), c_int)
      zone_case(1:m) = int(path%zone_case(1:m), c_int)
      a_star(1:m) = path%a_star(1:m); c_star(1:m) = path%c_star(1:m)
      p_star(1:m) = path%p_star(1:m); gbar(1:m) = path%gbar(1:m)
      n_events = int(path%n, c_int)
      w_star = path%w_star; w_fraction = path%w_fraction; g_touch = path%g_touch
      if (path%n > capacity) then
         stat = wa_capacity_too_small
         message = "fa_gap_path: capacity too small"
      end if
   end if
   status = int(stat, c_int)
end subroutine fa_gap_path

!> Critical values under gap control for one alpha over n values of mu, in one call of
!> wa_gapcritical::gap_critical_sweep: values(:, i) in the order of gap_critical_names.
!> Model and alpha are checked first, then every mu: the first invalid mu is reported
!> through ifail (1-based), nothing is computed and every value is NaN. A mu whose cycle
!> fails gets NaN in its column and its status in row_status; status/message are those
!> of the first failing row.
subroutine fa_gap_critical_sweep(n, model, alpha, mu, values, row_status, ifail, status, &
      message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok
   use wa_params, only: params_type, new_params
   use wa_models, only: check_model
   use wa_gapcritical, only: gap_critical_sweep, gap_critical_count
   implicit none
   !> Number of mu values
   integer(c_int), intent(in) :: n
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameters, >= 0
   real(c_double), intent(in) :: mu(n)
   !> The 10 critical values of each mu (gap_critical_names)
   real(c_double), intent(out) :: values(10, n)
   !> Status of each row (wa_ok where its values were computed)
   integer(c_int), intent(out) :: row_status(n)
   !> Index of the invalid mu (1-based), 0 when every mu is valid
   integer(c_int), intent(out) :: ifail
   !> wa_ok or the first failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   integer, allocatable :: row_stat(:)
   integer :: i, stat

   message = ""
   ifail = 0
   values = ieee_value(1.0_c_double, ieee_quiet_nan)
   call check_model(int(model), stat, message)
   if (stat == wa_ok) call new_params(alpha, 0.0_c_double, params, stat, message)
   do i = 1, n
      if (stat /= wa_ok) exit
      call new_params(alpha, mu(i), params, stat, message)
      if (stat /= wa_ok) ifail = i
   end do
   row_status = int(stat, c_int)
   if (stat == wa_ok .and. n > 0 .and. gap_critical_count == 10) then
      allocate (row_stat(n))
      call gap_critical_sweep(int(model), alpha, mu, values, stat, message, row_stat)
      row_status = int(row_stat, c_int)
   end if
   status = int(stat, c_int)
end subroutine fa_gap_critical_sweep


!> The status and message of one point of wa_gapcritical::gap_critical_sweep, its own
!> (a sweep's message is about its first failing row and counts the failures).
subroutine fa_gap_critical_message(model, alpha, mu, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_gapcritical, only: gap_critical_sweep, gap_critical_count
   implicit none
   !> Model constant: 0 westergaard, 1 jkr, 2 dw, 3 md
   integer(c_int), intent(in) :: model
   !> Johnson's parameter and the transition parameter of the point
   real(c_double), intent(in) :: alpha, mu
   !> The point's status (wa_ok when it is computed)
   integer(c_int), intent(out) :: status
   !> Its message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   real(c_double) :: values(gap_critical_count, 1)
   integer :: row_stat(1), stat
   character(len=256) :: row_msg(1)

   message = ""
   call gap_critical_sweep(int(model), alpha, [mu], values, stat, message, row_stat, row_msg)
   if (row_stat(1) /= 0) then                  ! else the sweep's own check failed
      stat = row_stat(1)
      if (len_trim(row_msg(1)) > 0) message = row_msg(1)
   end if
   status = int(stat, c_int)
end subroutine fa_gap_critical_message

!> The smooth (Lennard-Jones) model's equilibrium curve from far apart to full contact
!> on the grid of n points per period (0: automatic), the profile the sinusoid or the m
!> samples of one period in profile: the first min(n_points, capacity) points;
!> status 4 (capacity too small) when n_points > capacity. On other failures n_points = 0.
!> values: P_fc, P_fc_err, P_pf, P_pf_err, W*, W_star_err of the paths on this curve, the
!> errors from the cycle at N/2 (NaN where a path or the coarse cycle failed: the curve is
!> still returned, as by the CLI's `branch --model lj`).
subroutine fa_lj_trace(capacity, alpha, mu, n, use_profile, m, profile, p_star, gbar, a_star, b_star, &
      h_min, h_max, stable_load, stable_gap, event, extremum, n_points, n_period, values, &
      status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_bem_solver, only: lj_problem_type, lj_problem
   use wa_bem_trace, only: lj_branch_type, lj_trace
   use wa_bem_path, only: lj_cycle_type, lj_cycle, lj_paths
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   !> Length of the output arrays, >= 1
   integer(c_int), intent(in) :: capacity
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, > 0
   real(c_double), intent(in) :: mu
   !> Grid points per period (0: automatic)
   integer(c_int), intent(in) :: n
   !> 1: the profile is the samples in profile; 0: the sinusoid (profile ignored)
   integer(c_int), intent(in) :: use_profile
   !> Number of profile samples
   integer(c_int), intent(in) :: m
   !> Heights over Delta at x* = j/m, j = 0..m-1
   real(c_double), intent(in) :: profile(m)
   !> P*, gbar*, a*, b*, the smallest and largest gap of each point
   real(c_double), intent(out) :: p_star(capacity), gbar(capacity), a_star(capacity), &
      b_star(capacity), h_min(capacity), h_max(capacity)
   !> 1 where stable under load control / gap control, else 0
   integer(c_int), intent(out) :: stable_load(capacity), stable_gap(capacity)
   !> Event code (0, 1 fold of P*, 14 fold of gbar*, 5, 15, 8) and extremum (+-1 P*, +-2 gbar*)
   integer(c_int), intent(out) :: event(capacity), extremum(capacity)
   !> Number of points (may exceed capacity)
   integer(c_int), intent(out) :: n_points
   !> Grid points per period used
   integer(c_int), intent(out) :: n_period
   !> P_fc, P_fc_err, P_pf, P_pf_err, W_star, W_star_err on this curve (NaN: not computed)
   real(c_double), intent(out) :: values(6)
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(lj_problem_type) :: problem
   type(lj_branch_type) :: b, walked
   type(lj_cycle_type) :: cycle, coarse
   real(c_double), allocatable :: prof(:)
   character(len=256) :: side
   integer :: k, stat, st2

   message = ""
   p_star = 0; gbar = 0; a_star = 0; b_star = 0; h_min = 0; h_max = 0
   stable_load = 0; stable_gap = 0; event = 0; extremum = 0; n_points = 0; n_period = 0
   values = ieee_value(1.0_c_double, ieee_quiet_nan)
   if (use_profile /= 0) prof = profile     ! else unallocated: absent, the sinusoid
   call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call lj_problem(params, problem, stat, message, int(n), prof)
   if (stat == wa_ok) call lj_trace(problem, b, stat, message)
   if (stat == wa_ok) then
      k = min(b%n, int(capacity))
      p_star(1:k) = b%p_star(1:k); gbar(1:k) = b%gbar(1:k)
      a_star(1:k) = b%a_star(1:k); b_star(1:k) = b%b_star(1:k)
      h_min(1:k) = b%h_min(1:k); h_max(1:k) = b%h_max(1:k)
      stable_load(1:k) = merge(1_c_int, 0_c_int, b%stable_load(1:k))
      stable_gap(1:k) = merge(1_c_int, 0_c_int, b%stable_gap(1:k))
      event(1:k) = int(b%event(1:k), c_int); extremum(1:k) = int(b%extremum(1:k), c_int)
      n_points = int(b%n, c_int)
      n_period = int(b%n_period, c_int)
      if (b%n > capacity) then
         stat = wa_capacity_too_small
         message = "fa_lj_trace: capacity too small"
      end if
   end if
   if (stat == wa_ok) then               ! the paths on a copy (they insert landing states)
      walked = b
      side = ""
      call lj_paths(problem, walked, cycle, st2, side)
      if (st2 == wa_ok) values([1, 3, 5]) = [cycle%p_fc, cycle%p_pf, cycle%w_star]
      if (st2 == wa_ok) call lj_cycle(params, coarse, st2, side, b%n_period/2, prof, .false.)
      if (st2 == wa_ok) values([2, 4, 6]) = abs([cycle%p_fc - coarse%p_fc, &
         cycle%p_pf - coarse%p_pf, cycle%w_star - coarse%w_star])
   end if
   status = int(stat, c_int)
end subroutine fa_lj_trace

!> The smooth (Lennard-Jones) model's cycle: the events of the load-controlled path
!> (loading, unloading) and of the gap-controlled path (approach, retraction), P_fc*,
!> P_pf*, the snap load, W* and their error estimates |value at N - value at N/2|
!> (estimate = 0: not computed, 0). On failure the counts are 0 and the values NaN.
subroutine fa_lj_cycle(capacity, alpha, mu, n, use_profile, m, profile, estimate, n_max, l_stage, &
      l_event, l_a, l_p, l_g, n_load, g_stage, g_event, g_a, g_p, g_g, n_gap, values, n_period, &
      status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_bem_path, only: lj_cycle_type, lj_cycle
   implicit none
   !> Length of the event arrays, >= 1 (a path holds at most 64 events)
   integer(c_int), intent(in) :: capacity
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, > 0
   real(c_double), intent(in) :: mu
   !> Grid points per period (0: automatic)
   integer(c_int), intent(in) :: n
   !> 1: the profile is the samples in profile; 0: the sinusoid (profile ignored)
   integer(c_int), intent(in) :: use_profile
   !> Number of profile samples
   integer(c_int), intent(in) :: m
   !> Heights over Delta at x* = j/m, j = 0..m-1
   real(c_double), intent(in) :: profile(m)
   !> 1: estimate the discretisation errors (the cycle again at N/2); 0: not
   integer(c_int), intent(in) :: estimate
   !> Cap of the automatic grid (0: the library's, 2048; else in [128, 16384])
   integer(c_int), intent(in) :: n_max
   !> Load path: stage (1 loading, 2 unloading), event, a*, P*, gbar* of each event
   integer(c_int), intent(out) :: l_stage(capacity), l_event(capacity)
   real(c_double), intent(out) :: l_a(capacity), l_p(capacity), l_g(capacity)
   !> Number of load-path events (may exceed capacity)
   integer(c_int), intent(out) :: n_load
   !> Gap path: stage (1 approach, 2 retraction), event, a*, P*, gbar* of each event
   integer(c_int), intent(out) :: g_stage(capacity), g_event(capacity)
   real(c_double), intent(out) :: g_a(capacity), g_p(capacity), g_g(capacity)
   !> Number of gap-path events (may exceed capacity)
   integer(c_int), intent(out) :: n_gap
   !> P_fc, P_pf, P_snap, W_star, W_fraction, P_fc_err, P_pf_err, P_snap_err, W_star_err,
   !> fc_by_jump, pf_by_jump (1 or 0), P_fc_peak, P_fc_peak_err, fc_peak_by_jump (1 or 0)
   real(c_double), intent(out) :: values(14)
   !> Grid points per period used
   integer(c_int), intent(out) :: n_period
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(lj_cycle_type) :: c
   real(c_double), allocatable :: prof(:)
   integer :: stat, k

   message = ""
   l_stage = 0; l_event = 0; l_a = 0; l_p = 0; l_g = 0; n_load = 0
   g_stage = 0; g_event = 0; g_a = 0; g_p = 0; g_g = 0; n_gap = 0; n_period = 0
   values = ieee_value(1.0_c_double, ieee_quiet_nan)
   if (use_profile /= 0) prof = profile     ! else unallocated: absent, the sinusoid
   call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call lj_cycle(params, c, stat, message, int(n), prof, estimate /= 0, &
      int(n_max))
   if (stat == wa_ok) then
      k = min(c%load%n, int(capacity))
      l_stage(1:k) = int(c%load%stage(1:k), c_int); l_event(1:k) = int(c%load%event(1:k), c_int)
      l_a(1:k) = c%load%a_star(1:k); l_p(1:k) = c%load%p_star(1:k)
      l_g(1:k) = c%load%gbar(1:k)
      n_load = int(c%load%n, c_int)
      k = min(c%gap%n, int(capacity))
      g_stage(1:k) = int(c%gap%stage(1:k), c_int); g_event(1:k) = int(c%gap%event(1:k), c_int)
      g_a(1:k) = c%gap%a_star(1:k); g_p(1:k) = c%gap%p_star(1:k)
      g_g(1:k) = c%gap%gbar(1:k)
      n_gap = int(c%gap%n, c_int)
      values = [c%p_fc, c%p_pf, c%p_snap, c%w_star, c%w_fraction, c%p_fc_err, c%p_pf_err, &
         c%p_snap_err, c%w_star_err, merge(1.0_c_double, 0.0_c_double, c%fc_by_jump), &
         merge(1.0_c_double, 0.0_c_double, c%pf_by_jump), c%p_fc_peak, c%p_fc_peak_err, &
         merge(1.0_c_double, 0.0_c_double, c%fc_peak_by_jump)]
      n_period = int(c%n_period, c_int)
      if (max(n_load, n_gap) > capacity) then
         stat = wa_capacity_too_small
         message = "fa_lj_cycle: capacity too small"
      end if
   end if
   status = int(stat, c_int)
end subroutine fa_lj_cycle

!> Gap and traction over the period of one state of the smooth (Lennard-Jones) model:
!> lj_state_at_a (the traced state with a* nearest a_target, among the load-stable states
!> when there are any), at the N grid nodes x* = j/N - 1/2, j = 0..N-1.
!> Status 4 (capacity too small) when N > capacity (n_period says how many are needed).
subroutine fa_lj_profile(capacity, alpha, mu, n, use_profile, m, profile, a_target, x, &
      traction, gap, n_period, state, status, message)
   use, intrinsic :: iso_c_binding, only: c_int, c_double
   use wa_status, only: wa_ok, wa_capacity_too_small
   use wa_params, only: params_type, new_params
   use wa_bem_solver, only: lj_problem_type, lj_problem
   use wa_bem_state, only: lj_state_type, lj_state_at_a
   implicit none
   !> Length of the output arrays, >= 1
   integer(c_int), intent(in) :: capacity
   !> Johnson's parameter, > 0
   real(c_double), intent(in) :: alpha
   !> Transition parameter, > 0
   real(c_double), intent(in) :: mu
   !> Grid points per period (0: automatic)
   integer(c_int), intent(in) :: n
   !> 1: the profile is the samples in profile; 0: the sinusoid (profile ignored)
   integer(c_int), intent(in) :: use_profile
   !> Number of profile samples
   integer(c_int), intent(in) :: m
   !> Heights over Delta at x* = j/m, j = 0..m-1
   real(c_double), intent(in) :: profile(m)
   !> The contact half-width a* of the state wanted, in [0, 1/2]
   real(c_double), intent(in) :: a_target
   !> x*, traction p/p* (compressive positive) and gap h/Delta at the grid nodes
   real(c_double), intent(out) :: x(capacity), traction(capacity), gap(capacity)
   !> Grid points per period (the number of points)
   integer(c_int), intent(out) :: n_period
   !> The state drawn: a*, b*, P*, gbar*
   real(c_double), intent(out) :: state(4)
   !> wa_ok or the failure's status
   integer(c_int), intent(out) :: status
   !> The failure's message
   character(len=256), intent(out) :: message
   !f2py threadsafe
   type(params_type) :: params
   type(lj_problem_type) :: problem
   type(lj_state_type) :: s
   real(c_double), allocatable :: prof(:)
   integer :: np, stat

   message = ""
   x = 0; traction = 0; gap = 0; n_period = 0; state = 0
   if (use_profile /= 0) prof = profile     ! else unallocated: absent, the sinusoid
   call new_params(alpha, mu, params, stat, message)
   if (stat == wa_ok) call lj_problem(params, problem, stat, message, int(n), prof)
   if (stat == wa_ok) call lj_state_at_a(problem, a_target, s, stat, message)
   if (stat == wa_ok) then
      np = s%n_period
      n_period = int(np, c_int)
      state = [s%a_star, s%b_star, s%p_star, s%gbar]
      if (np > capacity) then
         stat = wa_capacity_too_small
         message = "fa_lj_profile: capacity too small"
      else
         x(1:np) = s%x
         traction(1:np) = s%traction
         gap(1:np) = s%gap
      end if
   end if
   status = int(stat, c_int)
end subroutine fa_lj_profile
