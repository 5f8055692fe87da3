!> Load-controlled loading and unloading along a traced branch, and the critical forces
!> P_fc* (full contact reached) and P_pf* (pull-off), exactly as doc/theory.md ("Load paths and critical forces") defines
!> them. Between consecutive extrema of P* the branch is monotone, so a jump at constant
!> load lands on the nearest stable piece that spans that load; the landing point is
!> then solved to full precision.
module wa_loadpath
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_negative_inf, ieee_quiet_nan
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_no_solution, set_error, wa_numerical_error, wa_not_converged
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact, &
      model_westergaard, model_jkr, model_dw, model_md
   use wa_branch, only: branch_type, trace_branch, event_jump_start, event_jump_end, &
      event_branch_end, &
      event_full_contact_reached, event_full_contact_left, event_pull_off
   use wa_curve, only: curve_equilibrium
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_text, only: real_text, int_text
   use wa_validate, only: optval
   use wa_mechanism, only: a_point_pull_off, mechanism_bisection, bisection_start, bisection_next, &
      bisection_tell, bisection_result
   implicit none
   private

   public :: path_type, load_path, critical_forces, path_from_branch
   public :: stage_loading, stage_unloading, critical_sweep, mechanism_change
   public :: mechanism_gradual, mechanism_jump_case1, mechanism_jump_case2, mechanism_snap

   integer, parameter :: stage_loading = 1, stage_unloading = 2
   !> Bound on the jumps of one loading or unloading (a path holds at most 64 events)
   integer, parameter :: max_jumps = 15
   !> Where a gradual pull-off is evaluated: the limit a* -> 0 to ~1e-12 in P*.
   real(wp), parameter :: a_limit = 1.0e-12_wp
   !> The mechanisms: gradual (no jump), a jump leaving a case-1 or a case-2 state, or
   !> (full contact only) a snap from separation at zero load.
   integer, parameter :: mechanism_gradual = 0, mechanism_jump_case1 = 1, &
      mechanism_jump_case2 = 2, mechanism_snap = 3

   !> The events of one loading-unloading cycle, in order.
   type :: path_type
      integer :: n = 0
      integer :: stage(64) = 0, event(64) = 0
      real(wp) :: a_star(64) = 0.0_wp, c_star(64) = 0.0_wp, p_star(64) = 0.0_wp
      !> Load at which full contact is first reached, and pull-off load (-Infinity: never)
      real(wp) :: p_fc = 0.0_wp, p_pf = 0.0_wp
      !> True where full contact is reached by a jump / contact is lost by a jump
      logical :: fc_by_jump = .false., pf_by_jump = .false.
      !> How full contact is reached / contact is lost (mechanism_* codes)
      integer :: fc_mechanism = 0, pf_mechanism = 0
      !> Area of the P*-a* hysteresis loop (not an energy: doc/theory.md, "Separation: gap, mean gap, displacement control, energy")
      real(wp) :: loop_area = 0.0_wp
   end type path_type

   !> Vertices of the hysteresis loop in the (a*, P*) plane.
   type :: polyline
      integer :: n = 0
      real(wp), allocatable :: xy(:, :)
   end type polyline



contains

   !> Trace the branch, then follow loading and unloading on it.
   subroutine load_path(model, params, path, status, errmsg)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The loading-unloading cycle: its events, P_fc*, P_pf*, their mechanisms, loop area
      type(path_type), intent(out) :: path
      !> wa_ok; wa_invalid_argument for bad input; else the status of the failing trace or
      !> jump
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      call trace_branch(model, params, branch, status, errmsg)
      if (status /= wa_ok) return
      call path_from_branch(model, params, branch, path, status, errmsg)
   end subroutine load_path

   !> P_fc* and P_pf* only (the loop area is not computed).
   subroutine critical_forces(model, params, p_fc, p_pf, status, errmsg)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The full-contact load P_fc* (over p*): where loading first reaches full contact
      real(wp), intent(out) :: p_fc
      !> The pull-off load P_pf* (over p*, <= 0): where unloading loses contact
      real(wp), intent(out) :: p_pf
      !> wa_ok; wa_invalid_argument for bad input; else the status of the failing trace or
      !> jump
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(path_type) :: path
      call load_path(model, params, path, status, errmsg)
      p_fc = path%p_fc
      p_pf = path%p_pf
   end subroutine critical_forces

   !> Loading from separation at P* = 0, then unloading from full contact.
   !> mechanisms_only (default false): the mechanisms, and which points jump, without
   !> solving the landing points or P*(a* -> 0) (events at the traced points; p_fc, p_pf
   !> and the loop area are then those of the traced points): what the adhesion map needs.
   subroutine path_from_branch(model, params, branch, path, status, errmsg, mechanisms_only)
      !> The model the branch was traced for
      integer, intent(in) :: model
      !> The parameters the branch was traced with
      type(params_type), intent(in) :: params
      !> A branch traced by trace_branch (status wa_ok)
      type(branch_type), intent(in) :: branch
      !> The loading-unloading cycle: its events, P_fc*, P_pf*, their mechanisms, loop area
      type(path_type), intent(out) :: path
      !> wa_ok, or the status of a landing point that cannot be solved
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> If true, only the mechanisms and which points jump (no landing points solved);
      !> default false
      logical, intent(in), optional :: mechanisms_only
      type(polyline) :: loop
      logical :: solve
      solve = .not. optval(mechanisms_only, .false.)
      call loading(model, params, branch, path, loop, status, errmsg, solve)
      if (status /= wa_ok) return
      call unloading(model, params, branch, path, loop, status, errmsg, solve)
      if (status /= wa_ok) return
      path%loop_area = enclosed_area(loop)
   end subroutine path_from_branch

   !> Jump in at P* = 0, rise along stable pieces, jump at every maximum, until full contact.
   subroutine loading(model, params, branch, path, loop, status, errmsg, solve)
      integer, intent(in) :: model
      logical, intent(in) :: solve
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(path_type), intent(inout) :: path
      type(polyline), intent(inout) :: loop
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: s
      integer :: k, seg, jumps
      real(wp) :: load

      status = wa_ok
      call add(path, stage_loading, event_jump_start, 0.0_wp, 0.0_wp, 0.0_wp)
      call vertex(loop, 0.0_wp, 0.0_wp)
      seg = landing_segment(branch, 0.0_wp, 0.0_wp, +1)
      if (branch%p_star(1) >= 0.0_wp .and. stable_segment(branch, 1)) seg = 1   ! in contact from a* -> 0
      load = 0.0_wp
      path%fc_mechanism = mechanism_snap
      do jumps = 1, max_jumps
         if (seg == 0) then                          ! nothing stable ahead: snap to full contact
            call add(path, stage_loading, event_full_contact_reached, 0.5_wp, 0.5_wp, load)
            call vertex(loop, 0.5_wp, load)
            path%p_fc = load
            path%fc_by_jump = .true.
            return
         end if
         if ((seg == 1 .and. branch%p_star(1) >= load) .or. .not. solve) then
            s%a_star = branch%a_star(seg)                   ! in contact from a* -> 0 on
            s%c_star = branch%c_star(seg)
         else
            call solve_on_segment(model, params, branch, seg, load, s, status, errmsg)
            if (status /= wa_ok) return
         end if
         call add(path, stage_loading, event_jump_end, s%a_star, s%c_star, load)
         call vertex(loop, s%a_star, load)
         k = piece_end(branch, seg, +1)              ! rise while the piece is stable
         call follow(loop, branch, merge(seg + 1, seg, branch%p_star(seg + 1) > &
            branch%p_star(seg)), k)
         if (branch%a_star(k) >= 0.5_wp) then
            path%p_fc = branch%p_star(k)
            path%fc_mechanism = mechanism_gradual
            call add(path, stage_loading, event_full_contact_reached, 0.5_wp, 0.5_wp, path%p_fc)
            return
         end if
         if (.not. (branch%p_star(k) > load)) exit  ! each stable piece must raise the load
         load = branch%p_star(k)
         path%fc_mechanism = jump_from(branch%zone_case(k))
         call add(path, stage_loading, event_jump_start, branch%a_star(k), branch%c_star(k), load)
         seg = landing_segment(branch, branch%a_star(k), load, +1)
      end do
      call set_error(wa_numerical_error, "load_path: loading makes no progress along the "// &
         "traced branch (a stable piece that does not raise the load)", status, errmsg)
   end subroutine loading

   !> Leave full contact at P*(a* -> 1/2), fall along stable pieces, jump at every
   !> minimum, until contact is lost at a fold or as a* shrinks to zero.
   subroutine unloading(model, params, branch, path, loop, status, errmsg, solve)
      integer, intent(in) :: model
      logical, intent(in) :: solve
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(path_type), intent(inout) :: path
      type(polyline), intent(inout) :: loop
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: s
      integer :: k, seg, jumps
      real(wp) :: load

      status = wa_ok
      if (model == model_jkr) then                    ! full contact never releases (3.4)
         path%p_pf = ieee_value(path%p_pf, ieee_negative_inf)
         call add(path, stage_unloading, event_pull_off, 0.5_wp, 0.5_wp, path%p_pf)
         return
      end if
      k = branch%n
      load = branch%p_star(k)
      call add(path, stage_unloading, event_full_contact_left, 0.5_wp, 0.5_wp, load)
      call vertex(loop, 0.5_wp, load)
      seg = 0
      if (stable_segment(branch, k - 1)) seg = k - 1  ! else the end itself is a minimum
      do jumps = 1, max_jumps
         if (seg > 0) then                            ! fall while the piece is stable
            k = piece_end(branch, seg, -1)
            call follow(loop, branch, merge(seg + 1, seg, branch%p_star(seg + 1) < &
               branch%p_star(seg)), k)
            if (branch%event(k) == event_branch_end) then   ! shrinks gradually to a* -> 0
               if (solve) then
                  call curve_equilibrium(model, params, a_limit, branch%c_star(k), s, &
                     status, errmsg)
                  if (status /= wa_ok) return
               else
                  s%a_star = a_limit
                  s%c_star = branch%c_star(k)
                  s%p_star = branch%p_star(k)
               end if
               path%p_pf = s%p_star
               call add(path, stage_unloading, event_pull_off, s%a_star, s%c_star, path%p_pf)
               call vertex(loop, 0.0_wp, path%p_pf)
               return
            end if
            if (.not. (branch%p_star(k) < load)) exit  ! each stable piece must lower it
            load = branch%p_star(k)
         end if
         call add(path, stage_unloading, event_jump_start, branch%a_star(k), &
            branch%c_star(k), load)
         seg = landing_segment(branch, branch%a_star(k), load, -1)
         if (seg == 0) then                          ! nothing stable below: pull-off
            path%p_pf = load
            path%pf_by_jump = .true.
            path%pf_mechanism = jump_from(branch%zone_case(k))
            if (branch%a_star(k) < a_point_pull_off) then
               path%pf_mechanism = mechanism_gradual     ! contact shrank to a point first
               path%pf_by_jump = .false.
            end if
            call add(path, stage_unloading, event_pull_off, branch%a_star(k), &
               branch%c_star(k), load)
            call vertex(loop, 0.0_wp, load)
            return
         end if
         if (solve) then
            call solve_on_segment(model, params, branch, seg, load, s, status, errmsg)
            if (status /= wa_ok) return
         else
            s%a_star = branch%a_star(seg)
            s%c_star = branch%c_star(seg)
         end if
         call add(path, stage_unloading, event_jump_end, s%a_star, s%c_star, load)
         call vertex(loop, s%a_star, load)
      end do
      call set_error(wa_numerical_error, "load_path: unloading makes no progress along the "// &
         "traced branch (a stable piece that does not lower the load)", status, errmsg)
   end subroutine unloading

   pure integer function jump_from(zone_case)
      integer, intent(in) :: zone_case
      jump_from = merge(mechanism_jump_case1, mechanism_jump_case2, zone_case == zone_inside)
   end function jump_from

   !> P_fc*, P_pf* and their mechanisms for one alpha over many mu. A failing mu never
   !> stops the sweep: its row gets NaN forces and mechanisms -1 and every other row is
   !> computed. status is wa_ok when every row succeeded, else the status of the first
   !> failing row, with errmsg naming its mu and the number of failing rows.
   !> row_status and row_errmsg (optional, size(mu)) receive each row's own status and
   !> message ("" for rows that succeeded).
   subroutine critical_sweep(model, alpha, mu, p_fc, p_pf, fc_mechanism, pf_mechanism, &
         status, errmsg, row_status, row_errmsg)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Johnson's parameter alpha of every row, in [alpha_min, alpha_max]
      real(wp), intent(in) :: alpha
      !> The mu of each row, 0 or in [mu_min, mu_max] (a bad one fails its row only)
      real(wp), intent(in) :: mu(:)
      !> P_fc* of each row (size(mu)); NaN where the row failed
      real(wp), intent(out) :: p_fc(:)
      !> P_pf* of each row (size(mu)); NaN where the row failed
      real(wp), intent(out) :: p_pf(:)
      !> Full-contact mechanism (mechanism_* code) of each row (size(mu)); -1 where it failed
      integer, intent(out) :: fc_mechanism(:)
      !> Pull-off mechanism (mechanism_* code) of each row (size(mu)); -1 where it failed
      integer, intent(out) :: pf_mechanism(:)
      !> wa_ok when every row succeeded, else the status of the first failing row
      integer, intent(out) :: status
      !> Receives the first failing row's mu and reason, and the number of failing rows
      character(len=*), intent(inout), optional :: errmsg
      !> Receives each row's own status (size(mu))
      integer, intent(out), optional :: row_status(:)
      !> Receives each row's own message, "" where it succeeded (size(mu))
      character(len=*), intent(out), optional :: row_errmsg(:)
      type(params_type) :: params
      type(path_type) :: path
      character(len=256) :: msg, first_msg
      real(wp) :: first_mu
      integer :: i, stat, first_stat, n_failed
      status = wa_ok
      first_stat = wa_ok
      n_failed = 0
      first_mu = 0.0_wp
      do i = 1, size(mu)
         msg = ""
         call new_params(alpha, mu(i), params, stat, msg)
         if (stat == wa_ok) call load_path(model, params, path, stat, msg)
         if (present(row_status)) row_status(i) = stat
         if (present(row_errmsg)) row_errmsg(i) = ""
         if (stat == wa_ok) then
            p_fc(i) = path%p_fc
            p_pf(i) = path%p_pf
            fc_mechanism(i) = path%fc_mechanism
            pf_mechanism(i) = path%pf_mechanism
            cycle
         end if
         p_fc(i) = ieee_value(1.0_wp, ieee_quiet_nan)
         p_pf(i) = p_fc(i)
         fc_mechanism(i) = -1
         pf_mechanism(i) = -1
         if (present(row_errmsg)) row_errmsg(i) = msg
         n_failed = n_failed + 1
         if (n_failed == 1) then
            first_stat = stat
            first_msg = msg
            first_mu = mu(i)
         end if
      end do
      if (n_failed > 0) call set_error(first_stat, "mu = "//real_text(first_mu)//": "// &
         trim(first_msg)//" ("//int_text(n_failed)//" of "//int_text(size(mu))// &
         " rows failed; their forces are NaN)", status, errmsg)
   end subroutine critical_sweep

   !> Bisect mu in [mu_lo, mu_hi] (mechanisms differ at the ends, else wa_no_solution) to
   !> where the full-contact (which = 1) or pull-off (which = 2) mechanism changes, to 1e-10
   !> relative (geometric bisection; arithmetic while the lower end is 0). A trial mu where the load
   !> path fails is replaced by other points of the bracket (at 1/4, 3/4, 1/8, 7/8, 1/16,
   !> 15/16 of it); when all of them fail too, or after 200 steps, the bisection stops with
   !> wa_not_converged: `bracket` (optional) receives the interval still known to hold the
   !> change (on success too) and mu_change its midpoint.
   subroutine mechanism_change(model, alpha, which, mu_lo, mu_hi, mu_change, status, errmsg, &
         bracket)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Which mechanism: 1 how full contact is reached, 2 how contact is lost (pull-off)
      integer, intent(in) :: which
      !> Johnson's parameter alpha, in [alpha_min, alpha_max]
      real(wp), intent(in) :: alpha
      !> Lower end of the bracket in mu, 0 or in [mu_min, mu_max], below mu_hi
      real(wp), intent(in) :: mu_lo
      !> Upper end of the bracket in mu, in [mu_min, mu_max]
      real(wp), intent(in) :: mu_hi
      !> The mu where the mechanism changes (midpoint of the final bracket, 1e-10 relative)
      real(wp), intent(out) :: mu_change
      !> wa_ok; wa_no_solution when the mechanisms at mu_lo and mu_hi agree;
      !> wa_not_converged when the load paths fail inside the bracket; wa_invalid_argument
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> Receives the interval still known to hold the change (on success too)
      real(wp), intent(out), optional :: bracket(2)
      real(wp), parameter :: tries(7) = [0.5_wp, 0.25_wp, 0.75_wp, 0.125_wp, 0.875_wp, &
         0.0625_wp, 0.9375_wp]
      type(mechanism_bisection) :: bis
      character(len=256) :: msg
      real(wp) :: mu
      integer :: mechanism, stat
      logical :: more

      call bisection_start(bis, mu_lo, mu_hi, tries, "load path")
      do
         call bisection_next(bis, mu, more)
         if (.not. more) exit
         mechanism = load_mechanism(model, alpha, mu, which, stat, msg)
         call bisection_tell(bis, mechanism, stat, msg)
      end do
      call bisection_result(bis, mu_change, status, errmsg, bracket)
   end subroutine mechanism_change

   !> The full-contact (which = 1) or pull-off (which = 2) mechanism of the load path at
   !> (alpha, mu); -1 and stat /= wa_ok, with msg, where the path fails.
   integer function load_mechanism(model, alpha, mu, which, stat, msg) result(mechanism)
      integer, intent(in) :: model, which
      real(wp), intent(in) :: alpha, mu
      integer, intent(out) :: stat
      character(len=*), intent(out) :: msg
      type(params_type) :: params
      type(path_type) :: path
      mechanism = -1
      msg = ""
      call new_params(alpha, mu, params, stat, msg)
      if (stat /= wa_ok) return
      call load_path(model, params, path, stat, msg)
      if (stat /= wa_ok) return
      mechanism = merge(path%fc_mechanism, path%pf_mechanism, which == 1)
   end function load_mechanism


   !> From the stable segment [seg, seg+1], walk along the branch toward rising load
   !> (dir = +1, loading) or falling load (dir = -1) while the segments stay stable; the
   !> last point reached ends the stable piece: a fold, a corner extremum or an end of the
   !> branch. An a*-turn does not end it: stability changes only at extrema of P*.
   pure integer function piece_end(branch, seg, dir)
      type(branch_type), intent(in) :: branch
      integer, intent(in) :: seg, dir
      integer :: step, nxt
      step = merge(1, -1, (branch%p_star(seg + 1) - branch%p_star(seg))*dir > 0.0_wp)
      piece_end = merge(seg + 1, seg, step == 1)
      do
         nxt = piece_end + step
         if (nxt < 1 .or. nxt > branch%n) exit
         if (.not. stable_segment(branch, min(piece_end, nxt))) exit
         if ((branch%p_star(nxt) - branch%p_star(piece_end))*dir <= 0.0_wp) exit  ! extremum
         piece_end = nxt
      end do
   end function piece_end

   !> Points i and i+1 belong to the same piece of the curve (not end and next start).
   pure logical function joined(branch, i)
      type(branch_type), intent(in) :: branch
      integer, intent(in) :: i
      joined = .not. (branch%event(i) == event_branch_end .and. &
         branch%event(i + 1) == event_branch_end)
   end function joined

   !> The segment [i, i+1] of a rising (stable) piece that spans `load`, nearest to
   !> a_from in direction dir (+1: larger a*, -1: smaller a*); 0 if none.
   pure integer function landing_segment(branch, a_from, load, dir)
      type(branch_type), intent(in) :: branch
      real(wp), intent(in) :: a_from, load
      integer, intent(in) :: dir
      real(wp) :: best, a_mid
      integer :: i
      landing_segment = 0
      best = huge(1.0_wp)
      do i = 1, branch%n - 1
         if (.not. stable_segment(branch, i)) cycle
         if (.not. (min(branch%p_star(i), branch%p_star(i + 1)) <= load .and. &
            load <= max(branch%p_star(i), branch%p_star(i + 1)))) cycle
         a_mid = 0.5_wp*(branch%a_star(i) + branch%a_star(i + 1))
         if (dir*(a_mid - a_from) <= 0.0_wp) cycle
         if (abs(a_mid - a_from) < best) then
            best = abs(a_mid - a_from)
            landing_segment = i
         end if
      end do
   end function landing_segment

   !> Segment [i, i+1] lies on a stable piece (its ends are stable, or one end is the
   !> extremum or corner that bounds the piece and the other is stable), P* not constant.
   pure logical function stable_segment(branch, i)
      type(branch_type), intent(in) :: branch
      integer, intent(in) :: i
      stable_segment = joined(branch, i) .and. branch%p_star(i + 1) /= branch%p_star(i) &
         .and. (branch%stable(i) .or. branch%stable(i + 1))
   end function stable_segment

   !> The equilibrium on segment [seg, seg+1] whose load is `load` (Brent in a*).
   subroutine solve_on_segment(model, params, branch, seg, load, s, status, errmsg)
      integer, intent(in) :: model, seg
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      real(wp), intent(in) :: load
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: a
      logical :: done
      integer :: iter

      status = wa_ok
      call brent_init(solver, branch%a_star(seg), branch%p_star(seg) - load, &
         branch%a_star(seg + 1), branch%p_star(seg + 1) - load, 1.0e-15_wp)
      do iter = 1, 200
         call brent_propose(solver, a, done)
         if (done) exit
         call curve_equilibrium(model, params, a, branch%c_star(seg), s, status, errmsg)
         if (status /= wa_ok) return
         call brent_accept(solver, s%p_star - load)
      end do
      call curve_equilibrium(model, params, solver%b, branch%c_star(seg), s, status, errmsg)
      if (status == wa_ok .and. .not. done) call set_error(wa_numerical_error, &
         "load_path: landing point not converged", status, errmsg)
   end subroutine solve_on_segment

   subroutine add(path, stage, event, a, c, p)
      type(path_type), intent(inout) :: path
      integer, intent(in) :: stage, event
      real(wp), intent(in) :: a, c, p
      if (path%n == size(path%stage)) return
      path%n = path%n + 1
      path%stage(path%n) = stage
      path%event(path%n) = event
      path%a_star(path%n) = a
      path%c_star(path%n) = c
      path%p_star(path%n) = p
   end subroutine add

   !> Branch points i1..i2 (either order) appended to the loop polygon.
   pure subroutine follow(loop, branch, i1, i2)
      type(polyline), intent(inout) :: loop
      type(branch_type), intent(in) :: branch
      integer, intent(in) :: i1, i2
      integer :: i
      do i = i1, i2, merge(1, -1, i2 >= i1)
         call vertex(loop, branch%a_star(i), branch%p_star(i))
      end do
   end subroutine follow

   pure subroutine vertex(loop, a, p)
      type(polyline), intent(inout) :: loop
      real(wp), intent(in) :: a, p
      real(wp), allocatable :: tmp(:, :)
      if (.not. allocated(loop%xy)) allocate (loop%xy(2, 256))
      if (loop%n == size(loop%xy, 2)) then
         allocate (tmp(2, 2*loop%n))
         tmp(:, 1:loop%n) = loop%xy(:, 1:loop%n)
         call move_alloc(tmp, loop%xy)
      end if
      loop%n = loop%n + 1
      loop%xy(:, loop%n) = [a, p]
   end subroutine vertex

   !> Shoelace area of the closed loading-unloading polygon in the (a*, P*) plane.
   !> Trapezoidal along the branch points: relative accuracy ~ (step)^2, about 1e-4.
   pure real(wp) function enclosed_area(loop)
      type(polyline), intent(in) :: loop
      integer :: i, j
      enclosed_area = 0.0_wp
      do i = 1, loop%n
         j = merge(1, i + 1, i == loop%n)
         enclosed_area = enclosed_area + loop%xy(1, i)*loop%xy(2, j) - loop%xy(1, j)*loop%xy(2, i)
      end do
      enclosed_area = 0.5_wp*abs(enclosed_area)
   end function enclosed_area

end module wa_loadpath
