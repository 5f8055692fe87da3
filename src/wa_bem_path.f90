!> Load- and gap-controlled paths on a traced smooth-adhesion curve, the critical loads
!> P_fc* and P_pf*, the energy lost per gap-controlled cycle W* = -oint P* dgbar*, and the
!> same with their discretisation-error estimates (the cycle at N and at N/2), as the
!> other models report them (doc/theory.md, "Smooth adhesion", "Load paths", "Gap control").
!>
!> Rules (as for DW and MD): loading starts separated at P* = 0 and lands on the first
!> load-stable state at P* = 0 along the curve; it rises along load-stable pieces and at a
!> maximum of P* jumps at constant load to the next load-stable state further along the
!> curve; P_fc* is the load at which full contact (a* = 1/2) is first reached, P_fc,peak*
!> the load at which the peak tension's abscissa b* first reaches 1/2 (under the same
!> rules: a jump's load where a jump reaches it), the one comparable with DW's and MD's
!> P_fc* (their b* = a* + 0.4 (c* - a*) is 1/2 only in full contact). Unloading
!> starts at the end of the trace, falls, and at a minimum of P* jumps back along the
!> curve, or separates where no load-stable state at that load is left: P_pf*. Under gap
!> control the approach runs from far apart to the end of the trace and the retraction
!> back, jumping at constant gbar* at the extrema of gbar*. The landing states are solved
!> on the curve and inserted into the branch.
module wa_bem_path
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_no_solution, wa_not_converged, set_error
   use wa_params, only: params_type
   use wa_bem_law, only: bem_law_type, lj_law, law_eval, law_peak
   use wa_bem_elastic, only: full_period
   use wa_bem_solver, only: lj_problem_type, jacobian_type, point_info_type, factor_at, &
      point_info, lj_problem, gap_energy, jacobian_free
   use wa_bem_trace, only: lj_branch_type, lj_trace, lj_trace_options, lj_point_at, &
      branch_append, lj_event_load_fold, lj_event_gap_fold, lj_event_full_contact
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   implicit none
   private

   public :: lj_path_type, lj_cycle_type, lj_paths, lj_cycle, lj_rigid_pull_off
   public :: lj_stage_loading, lj_stage_unloading, lj_stage_approach, lj_stage_retraction
   public :: lj_path_jump_start, lj_path_jump_end, lj_path_full_contact_reached, &
      lj_path_full_contact_left, lj_path_pull_off

   integer, parameter :: lj_stage_loading = 1, lj_stage_unloading = 2, &
      lj_stage_approach = 1, lj_stage_retraction = 2
   !> Event codes of a path (those of the other models' paths)
   integer, parameter :: lj_path_jump_start = 3, lj_path_jump_end = 4, &
      lj_path_full_contact_reached = 5, lj_path_full_contact_left = 6, lj_path_pull_off = 7
   integer, parameter :: max_events = 64
   !> Bound on the jumps of one stage of a path (each jump records two events)
   integer, parameter :: max_path_jumps = 30
   !> quantity walked: the load or the mean gap; or solved for: the largest gap
   integer, parameter :: by_load = 1, by_gap = 2, by_h_max = 3

   !> The events of one cycle under one control, in order.
   type :: lj_path_type
      integer :: n = 0
      integer :: stage(max_events) = 0, event(max_events) = 0
      real(wp) :: p_star(max_events) = 0.0_wp, gbar(max_events) = 0.0_wp, &
         a_star(max_events) = 0.0_wp
      !> More events than max_events were to be recorded (lj_paths then fails)
      logical :: overflow = .false.
   end type lj_path_type

   !> Both paths and the critical values of one cycle, with error estimates.
   type :: lj_cycle_type
      type(lj_path_type) :: load, gap
      !> Full contact reached (loading) and pull-off load; true where by a jump
      real(wp) :: p_fc = 0.0_wp, p_pf = 0.0_wp
      logical :: fc_by_jump = .false., pf_by_jump = .false.
      !> Load of the last jump on loading (the snap towards full contact; P_fc* where
      !> loading has no jump): the JKR limit's P_fc*
      real(wp) :: p_snap = 0.0_wp
      !> Load at which b* (the abscissa of the peak tension, h = 3^(1/6) eps) first
      !> reaches 1/2 on loading, i.e. the largest gap falls to 3^(1/6) eps: the full-
      !> contact load comparable with the cohesive-zone models'; true where by a jump
      real(wp) :: p_fc_peak = 0.0_wp
      logical :: fc_peak_by_jump = .false.
      !> Energy lost per gap-controlled cycle (units p* Delta) and over pi alpha^2/2
      real(wp) :: w_star = 0.0_wp, w_fraction = 0.0_wp
      !> Grid points per period, and the estimated discretisation errors (|value at N -
      !> value at N/2|; 0 where the coarse cycle was not computed)
      integer :: n_period = 0
      real(wp) :: p_fc_err = 0.0_wp, p_pf_err = 0.0_wp, w_star_err = 0.0_wp, &
         p_snap_err = 0.0_wp, p_fc_peak_err = 0.0_wp
   end type lj_cycle_type

contains

   !> Pull-off of the rigid wave (alpha -> 0 at fixed eps/Delta), the plane-strain
   !> analogue of Bradley's: the crest as a parabola f = 2 pi^2 x^2 and eps << Delta give
   !>   P_pf* = -(8 dgamma/(3 sqrt(2 eps))) (9/34) t^(5/2),  t^6 = 15/(136 c9),
   !> c9 = 15!!/16!! = 6435/32768 (doc/theory.md, "Rigid limit"); dgamma = pi alpha^2/2
   !> and eps = (4 alpha^4)^(1/3)/mu in units of p* Delta and Delta.
   pure function lj_rigid_pull_off(params) result(p_pf)
      !> Validated dimensionless parameters alpha, mu (new_params), mu > 0 (mu = 0 has no
      !> LJ law); the result P_pf* is in units of p*
      type(params_type), intent(in) :: params
      real(wp) :: p_pf, t
      type(bem_law_type) :: law
      real(wp), parameter :: c9 = 6435.0_wp/32768.0_wp
      law = lj_law(params%alpha, params%mu)
      t = (15.0_wp/(136.0_wp*c9))**(1.0_wp/6.0_wp)
      p_pf = -(8.0_wp*law%dgamma/(3.0_wp*sqrt(2.0_wp*law%eps)))*(9.0_wp/34.0_wp)*t**2.5_wp
   end function lj_rigid_pull_off

   !> Trace, both paths and the critical values at the grid of n (0 or absent: automatic)
   !> and at half that grid, whose difference is the error estimate (skipped with
   !> estimate = .false.).
   recursive subroutine lj_cycle(params, cycle, status, errmsg, n, profile, estimate, n_max)
      !> Dimensionless parameters alpha, mu (new_params; checked again), mu > 0
      type(params_type), intent(in) :: params
      !> Both paths, P_fc*, P_fc,peak*, P_pf*, the snap load (over p*), W* (over p* Delta), W*/(pi
      !> alpha^2/2), N and the error estimates; on failure what was found before it (a
      !> failing coarse cycle leaves the cycle at N with the errors 0)
      type(lj_cycle_type), intent(out) :: cycle
      !> wa_ok, else the status of the failing step: lj_problem (wa_invalid_argument,
      !> wa_capacity_too_small), lj_trace (wa_not_converged, wa_capacity_too_small) or
      !> lj_paths (wa_no_solution, wa_not_converged), at N or at N/2
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> Grid points per period N, as in lj_problem (even, >= 8; 0 or absent: automatic);
      !> with the estimate N/2 must be valid too (N a multiple of 4, >= 16)
      integer, intent(in), optional :: n
      !> The profile as samples of one period over Delta, as in lj_problem (absent: the
      !> sinusoid 1 - cos 2 pi x*); the coarse cycle uses the same samples
      real(wp), intent(in), optional :: profile(:)
      !> If false, skip the cycle at N/2 (the error fields stay 0); default true
      logical, intent(in), optional :: estimate
      !> Cap of the automatic grid, as in lj_problem (0 or absent: 2048)
      integer, intent(in), optional :: n_max
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: branch
      type(lj_cycle_type) :: coarse
      logical :: with_estimate

      with_estimate = .true.
      if (present(estimate)) with_estimate = estimate
      call lj_problem(params, problem, status, errmsg, n, profile, n_max)
      if (status /= wa_ok) return
      call lj_trace(problem, branch, status, errmsg)
      if (status /= wa_ok) return
      call lj_paths(problem, branch, cycle, status, errmsg)
      if (status /= wa_ok) return
      cycle%w_fraction = cycle%w_star/(problem%law%dgamma)
      if (.not. with_estimate) return
      call lj_cycle(params, coarse, status, errmsg, problem%grid%n_period/2, profile, .false.)
      if (status /= wa_ok) return
      cycle%p_fc_err = abs(cycle%p_fc - coarse%p_fc)
      cycle%p_pf_err = abs(cycle%p_pf - coarse%p_pf)
      cycle%w_star_err = abs(cycle%w_star - coarse%w_star)
      cycle%p_snap_err = abs(cycle%p_snap - coarse%p_snap)
      cycle%p_fc_peak_err = abs(cycle%p_fc_peak - coarse%p_fc_peak)
   end subroutine lj_cycle

   !> Load- and gap-controlled paths on a traced branch (landing states are inserted).
   subroutine lj_paths(problem, branch, cycle, status, errmsg)
      !> The problem the branch was traced for
      type(lj_problem_type), intent(in) :: problem
      !> A branch traced by lj_trace (status wa_ok); the landing states of the jumps are
      !> inserted into it (also those found before a failure)
      type(lj_branch_type), intent(inout) :: branch
      !> A default-initialised cycle; receives N, the load path with P_fc*, P_fc,peak*, P_pf*, the snap
      !> load (over p*), and the gap path with W* (over p* Delta); W*/(pi alpha^2/2) and
      !> the error fields are left alone (lj_cycle sets them). On failure the path of the
      !> failing control is not stored (P_fc* may hold huge(1.0_wp) where loading fails)
      type(lj_cycle_type), intent(inout) :: cycle
      !> wa_ok; wa_no_solution where a path cannot be completed (no load-stable state at
      !> P* = 0, loading stops short of full contact, no stable landing state after a jump,
      !> a walk ends away from an extremum); wa_not_converged where an unloading landing
      !> state does not converge, a stage takes more than 30 jumps or a path more than 64
      !> events (the spurious folds of an unresolved grid)
      integer, intent(out) :: status
      !> Receives the reason on failure (what failed)
      character(len=*), intent(inout), optional :: errmsg
      cycle%n_period = problem%grid%n_period
      call load_control(problem, branch, cycle, status, errmsg)
      if (status /= wa_ok) return
      if (cycle%load%overflow) then
         call fail(wa_not_converged, "lj load path: more than 64 events (spurious folds of "// &
            "an unresolved grid? raise n)", errmsg, status)
         return
      end if
      call gap_control(problem, branch, cycle, status, errmsg)
      if (status == wa_ok .and. cycle%gap%overflow) call fail(wa_not_converged, &
         "lj gap path: more than 64 events (spurious folds of an unresolved grid? raise n)", &
         errmsg, status)
   end subroutine lj_paths

   !> Quantity q (by_load: P*, by_gap: gbar*, by_h_max: the largest gap) of point i.
   pure function q_of(branch, by, i) result(q)
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: by, i
      real(wp) :: q
      select case (by)
      case (by_load); q = branch%p_star(i)
      case (by_gap); q = branch%gbar(i)
      case default; q = branch%h_max(i)
      end select
   end function q_of

   !> Stable under the control of interval [i, i+1] (its inertia is constant: folds are
   !> points of the branch; take the end that is not an extremum).
   pure logical function interval_stable(branch, by, i)
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: by, i
      integer :: k
      k = i
      if (branch%extremum(i) /= 0) k = i + 1
      if (by == by_load) then
         interval_stable = branch%neg_load(k) == 0
      else
         interval_stable = branch%neg_gap(k) == 0
      end if
   end function interval_stable

   !> Fold of the walked quantity at point i: +1 maximum, -1 minimum, 0 none.
   pure integer function fold_of(branch, by, i)
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: by, i
      fold_of = 0
      if (by == by_load .and. abs(branch%extremum(i)) == 1) fold_of = branch%extremum(i)
      if (by == by_gap .and. abs(branch%extremum(i)) == 2) fold_of = branch%extremum(i)/2
   end function fold_of

   !> Walk from point i in direction dir along stable intervals while q moves in the sense
   !> `sense` (+1 rising, -1 falling); stops at a fold of q (returns its index), at the end
   !> of the branch, or where the interval turns unstable. Crossings of full contact are
   !> recorded.
   subroutine walk(branch, by, i, dir, path, stage)
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: by, dir, stage
      integer, intent(inout) :: i
      type(lj_path_type), intent(inout) :: path
      integer :: j
      do
         j = i + dir
         if (j < 1 .or. j > branch%n) return
         if (.not. interval_stable(branch, by, min(i, j))) return
         i = j
         if (branch%event(i) == lj_event_full_contact) call record(path, stage, &
            merge(lj_path_full_contact_reached, lj_path_full_contact_left, &
            branch%a_star(max(1, min(branch%n, i + dir))) >= 0.5_wp), branch, i)
         if (fold_of(branch, by, i) /= 0) return
      end do
   end subroutine walk

   subroutine record(path, stage, event, branch, i)
      type(lj_path_type), intent(inout) :: path
      integer, intent(in) :: stage, event, i
      type(lj_branch_type), intent(in) :: branch
      if (path%n >= max_events) then      ! flagged: the caller fails, never a cut path
         path%overflow = .true.
         return
      end if
      path%n = path%n + 1
      path%stage(path%n) = stage
      path%event(path%n) = event
      path%p_star(path%n) = branch%p_star(i)
      path%gbar(path%n) = branch%gbar(i)
      path%a_star(path%n) = branch%a_star(i)
   end subroutine record

   !> The first stable interval from point i in direction dir that crosses q = value; its
   !> state is solved and inserted into the branch; land = its index (0: none).
   subroutine find_landing(problem, branch, by, i, dir, value, land, status)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      integer, intent(in) :: by, i, dir
      real(wp), intent(in) :: value
      integer, intent(out) :: land, status
      integer :: j, k
      real(wp) :: q0, q1
      land = 0
      status = wa_ok
      j = i
      do
         k = j + dir
         if (k < 1 .or. k > branch%n) return
         if (interval_stable(branch, by, min(j, k))) then
            q0 = q_of(branch, by, min(j, k)) - value
            q1 = q_of(branch, by, max(j, k)) - value
            if (q0*q1 <= 0.0_wp .and. .not. (q0 == 0.0_wp .and. q1 == 0.0_wp)) then
               call insert_crossing(problem, branch, by, min(j, k), value, land, status)
               return
            end if
         end if
         j = k
      end do
   end subroutine find_landing

   !> Solve the state of interval [i, i+1] where q = value (Brent on the arclength) and
   !> insert it after i; land = i + 1. A crossing at an end is that end.
   subroutine insert_crossing(problem, branch, by, i, value, land, status)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      integer, intent(in) :: by, i
      real(wp), intent(in) :: value
      integer, intent(out) :: land, status
      type(jacobian_type) :: pre
      call crossing_with(problem, pre, branch, by, i, value, land, status)
      call jacobian_free(pre)
   end subroutine insert_crossing

   !> insert_crossing with the caller's workspace pre.
   subroutine crossing_with(problem, pre, branch, by, i, value, land, status)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: pre
      type(lj_branch_type), intent(inout) :: branch
      integer, intent(in) :: by, i
      real(wp), intent(in) :: value
      integer, intent(out) :: land, status
      type(point_info_type) :: info
      real(wp), allocatable :: z(:), t(:)
      real(wp) :: s
      integer :: n_factor, k
      if (q_of(branch, by, i) == value) then
         land = i; status = wa_ok; return
      else if (q_of(branch, by, i + 1) == value) then
         land = i + 1; status = wa_ok; return
      end if
      n_factor = 1
      call solve_crossing(problem, pre, branch, by, i, value, z, t, info, s, n_factor, status)
      if (status /= wa_ok) return
      call factor_at(problem, z, pre)
      n_factor = n_factor + 1
      if (problem%two_grid) then         ! the inertia of the interval (no fold inside)
         k = i
         if (branch%extremum(i) /= 0) k = i + 1
         pre%neg_load = branch%neg_load(k)
         pre%neg_gap = branch%neg_gap(k)
      end if
      call branch_append(problem, branch, z, t, info, branch%s(i) + s, pre%neg_load, &
         pre%neg_gap, 0, 0)
      call move_last(branch, i + 1)
      land = i + 1
      branch%n_factor = branch%n_factor + n_factor
   end subroutine crossing_with

   !> The state z (tangent t, info) of interval [i, i+1] where q = value, at arclength s
   !> from point i (Brent on the arclength; the ends must bracket it, neither equal).
   subroutine solve_crossing(problem, pre, branch, by, i, value, z, t, info, s, n_factor, &
         status)
      type(lj_problem_type), intent(in) :: problem
      type(jacobian_type), intent(inout) :: pre
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: by, i
      real(wp), intent(in) :: value
      real(wp), allocatable, intent(out) :: z(:), t(:)
      type(point_info_type), intent(out) :: info
      real(wp), intent(out) :: s
      integer, intent(inout) :: n_factor
      integer, intent(out) :: status
      type(brent_type) :: solver
      real(wp) :: ds, q
      integer :: it
      logical :: done
      call factor_at(problem, branch%z(:, i), pre)
      ds = branch%s(i + 1) - branch%s(i)
      call brent_init(solver, 0.0_wp, q_of(branch, by, i) - value, ds, &
         q_of(branch, by, i + 1) - value, 1.0e-12_wp*ds)
      do it = 1, 80
         call brent_propose(solver, s, done, settle=.true.)
         if (done) exit
         call lj_point_at(problem, branch%z(:, i), branch%t(:, i), pre, s, z, t, n_factor, &
            status)
         if (status /= wa_ok) return
         info = point_info(problem, z)
         select case (by)
         case (by_load); q = info%p
         case (by_gap); q = info%gbar
         case default; q = info%h_max
         end select
         call brent_accept(solver, q - value)
      end do
      s = solver%b
      call lj_point_at(problem, branch%z(:, i), branch%t(:, i), pre, s, z, t, n_factor, status)
      if (status /= wa_ok) return
      info = point_info(problem, z)
   end subroutine solve_crossing

   !> Move the last point of the branch to position k (the others shift up).
   subroutine move_last(branch, k)
      type(lj_branch_type), intent(inout) :: branch
      integer, intent(in) :: k
      integer :: n
      n = branch%n
      if (k == n) return
      branch%s(k:n) = cshift(branch%s(k:n), -1)
      branch%p_star(k:n) = cshift(branch%p_star(k:n), -1)
      branch%gbar(k:n) = cshift(branch%gbar(k:n), -1)
      branch%a_star(k:n) = cshift(branch%a_star(k:n), -1)
      branch%b_star(k:n) = cshift(branch%b_star(k:n), -1)
      branch%h_min(k:n) = cshift(branch%h_min(k:n), -1)
      branch%h_max(k:n) = cshift(branch%h_max(k:n), -1)
      branch%dp(k:n) = cshift(branch%dp(k:n), -1)
      branch%dg(k:n) = cshift(branch%dg(k:n), -1)
      branch%neg_load(k:n) = cshift(branch%neg_load(k:n), -1)
      branch%neg_gap(k:n) = cshift(branch%neg_gap(k:n), -1)
      branch%stable_load(k:n) = cshift(branch%stable_load(k:n), -1)
      branch%stable_gap(k:n) = cshift(branch%stable_gap(k:n), -1)
      branch%event(k:n) = cshift(branch%event(k:n), -1)
      branch%extremum(k:n) = cshift(branch%extremum(k:n), -1)
      branch%z(:, k:n) = cshift(branch%z(:, k:n), -1, dim=2)
      branch%t(:, k:n) = cshift(branch%t(:, k:n), -1, dim=2)
   end subroutine move_last

   !> Loading and unloading under load control: P_fc*, P_pf*.
   subroutine load_control(problem, branch, cycle, status, errmsg)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      type(lj_cycle_type), intent(inout) :: cycle
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer :: i, land, dir, jumps, start
      real(wp) :: pj
      logical :: landed, peak_found
      type(lj_path_type) :: path

      ! loading: land at P* = 0 on the first load-stable state along the curve
      call find_landing(problem, branch, by_load, 1, 1, 0.0_wp, land, status)
      if (status /= wa_ok .or. land == 0) then
         call fail(wa_no_solution, "lj load path: no load-stable state at P* = 0", errmsg, &
            status)
         return
      end if
      i = land
      call record(path, lj_stage_loading, lj_path_jump_end, branch, i)
      cycle%p_fc = huge(1.0_wp)
      peak_found = landed_at_peak(problem, branch, i, branch%p_star(i), cycle)
      do jumps = 1, 30
         if (branch%a_star(i) >= 0.5_wp) then        ! landed in full contact
            cycle%p_fc = branch%p_star(i)
            cycle%fc_by_jump = .true.
            call record(path, lj_stage_loading, lj_path_full_contact_reached, branch, i)
            exit
         end if
         dir = rising(branch, by_load, i, 1)
         start = i
         call walk(branch, by_load, i, dir, path, lj_stage_loading)
         if (.not. peak_found) then
            call peak_on_walk(problem, branch, start, i, dir, cycle, peak_found, status)
            if (status /= wa_ok) then
               call fail(status, "lj load path: the state where b* reaches 1/2 did not "// &
                  "converge", errmsg, status)
               return
            end if
         end if
         if (reached_full_contact(path, lj_stage_loading)) then
            cycle%p_fc = path%p_star(path%n)
            cycle%fc_by_jump = .false.
            exit
         end if
         if (fold_of(branch, by_load, i) /= 1) then
            call fail(wa_no_solution, "lj load path: loading stopped short of full contact", &
               errmsg, status)
            return
         end if
         pj = branch%p_star(i)
         cycle%p_snap = pj
         call jump(problem, branch, by_load, lj_stage_loading, 1, i, path, landed, status)
         if (status /= wa_ok .or. .not. landed) then
            call fail(wa_no_solution, "lj load path: no stable landing state after a jump", &
               errmsg, status)
            return
         end if
         if (.not. peak_found) peak_found = landed_at_peak(problem, branch, i, pj, cycle)
         if (branch%a_star(i) >= 0.5_wp) then
            cycle%p_fc = pj
            cycle%fc_by_jump = .true.
            call record(path, lj_stage_loading, lj_path_full_contact_reached, branch, i)
            exit
         end if
      end do
      if (cycle%p_fc == huge(1.0_wp)) then
         call fail(wa_not_converged, "lj load path: too many jumps on loading", errmsg, status)
         return
      end if
      if (.not. any(path%event(1:path%n) == lj_path_jump_start)) cycle%p_snap = cycle%p_fc
      ! unloading from the end of the trace
      i = branch%n
      do jumps = 1, 30
         dir = rising(branch, by_load, i, -1)
         call walk(branch, by_load, i, dir, path, lj_stage_unloading)
         if (fold_of(branch, by_load, i) /= -1) then
            call fail(wa_no_solution, "lj load path: unloading ended away from a minimum "// &
               "of P*", errmsg, status)
            return
         end if
         pj = branch%p_star(i)
         call jump(problem, branch, by_load, lj_stage_unloading, -1, i, path, landed, status)
         if (status /= wa_ok) then
            call fail(status, "lj load path: a landing state did not converge", errmsg, status)
            return
         end if
         if (.not. landed) then
            cycle%p_pf = pj
            cycle%pf_by_jump = .true.
            call record(path, lj_stage_unloading, lj_path_pull_off, branch, i)
            cycle%load = path
            return
         end if
      end do
      call fail(wa_not_converged, "lj load path: too many jumps on unloading", errmsg, status)
   end subroutine load_control

   !> True where the state landed on at point i (by a jump at load pj) has b* = 1/2 (its
   !> largest gap at most the peak tension's): P_fc,peak* = pj, by that jump.
   logical function landed_at_peak(problem, branch, i, pj, cycle) result(found)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: i
      real(wp), intent(in) :: pj
      type(lj_cycle_type), intent(inout) :: cycle
      found = branch%h_max(i) <= law_peak(problem%law)
      if (.not. found) return
      cycle%p_fc_peak = pj
      cycle%fc_peak_by_jump = .true.
   end function landed_at_peak

   !> P_fc,peak* on a loading walk from point i0 to i1 (direction dir): the load where
   !> the largest gap first falls to the peak tension's gap 3^(1/6) eps, solved on the
   !> curve inside the interval that brackets it (not inserted: the other paths keep
   !> their points). found false where the walk does not reach it.
   subroutine peak_on_walk(problem, branch, i0, i1, dir, cycle, found, status)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: i0, i1, dir
      type(lj_cycle_type), intent(inout) :: cycle
      logical, intent(out) :: found
      integer, intent(out) :: status
      type(jacobian_type) :: pre
      type(point_info_type) :: info
      real(wp), allocatable :: z(:), t(:)
      real(wp) :: peak, s
      integer :: k, n_factor
      peak = law_peak(problem%law)
      found = .false.
      status = wa_ok
      do k = i0, i1 - dir, dir
         if (branch%h_max(k + dir) <= peak) then
            found = .true.
            cycle%p_fc_peak = branch%p_star(k + dir)
            cycle%fc_peak_by_jump = .false.
            if (branch%h_max(k + dir) == peak .or. branch%h_max(k) <= peak) return
            n_factor = 0
            call solve_crossing(problem, pre, branch, by_h_max, min(k, k + dir), peak, z, &
               t, info, s, n_factor, status)
            call jacobian_free(pre)
            if (status == wa_ok) cycle%p_fc_peak = info%p
            return
         end if
      end do
   end subroutine peak_on_walk

   !> Approach and retraction under gap control, and W*.
   subroutine gap_control(problem, branch, cycle, status, errmsg)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      type(lj_cycle_type), intent(inout) :: cycle
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(jacobian_type) :: work
      call gap_walks(problem, branch, cycle, work, status, errmsg)
      call jacobian_free(work)
   end subroutine gap_control

   !> gap_control with the workspace work (FFT plans for the energies). The system is
   !> conservative between jumps (dPi/dgbar* = -P* along the curve, Pi = gap_energy), so
   !> W* = -oint P* dgbar* is the sum over the jumps of Pi(start) - Pi(end), both at the
   !> same gbar*: exact, no quadrature along the walks, and 0 without a jump.
   subroutine gap_walks(problem, branch, cycle, work, status, errmsg)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      type(lj_cycle_type), intent(inout) :: cycle
      type(jacobian_type), intent(inout) :: work
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer :: i, jumps, stage, dir, sense
      real(wp) :: lost, pi_start
      logical :: landed
      type(lj_path_type) :: path

      lost = 0.0_wp
      status = wa_ok
      do stage = lj_stage_approach, lj_stage_retraction
         if (stage == lj_stage_approach) then
            i = 1; dir = 1; sense = -1
         else
            i = branch%n; dir = -1; sense = 1
         end if
         do jumps = 1, max_path_jumps + 1
            call walk(branch, by_gap, i, dir, path, stage)
            if (i == 1 .or. i == branch%n) exit
            if (jumps > max_path_jumps) then      ! never a W* of a path cut short
               call fail(wa_not_converged, "lj gap path: more than 30 jumps on the "// &
                  trim(merge("approach  ", "retraction", stage == lj_stage_approach))// &
                  " (spurious folds of an unresolved grid? raise n)", errmsg, status)
               return
            end if
            if (fold_of(branch, by_gap, i) /= sense) then
               call fail(wa_no_solution, "lj gap path: the walk ended away from an "// &
                  "extremum of gbar*", errmsg, status)
               return
            end if
            pi_start = gap_energy(problem, work, branch%z(:, i))
            call jump(problem, branch, by_gap, stage, dir, i, path, landed, status)
            if (status /= wa_ok .or. .not. landed) then
               call fail(wa_no_solution, "lj gap path: no stable landing state after a jump", &
                  errmsg, status)
               return
            end if
            lost = lost + (pi_start - gap_energy(problem, work, branch%z(:, i)))
         end do
      end do
      cycle%gap = path
      cycle%w_star = lost
   end subroutine gap_walks

   !> A jump at constant q from the fold at point i towards dir: recorded, landed on the
   !> first stable state found (i moves there) or not (landed false, i kept).
   subroutine jump(problem, branch, by, stage, dir, i, path, landed, status)
      type(lj_problem_type), intent(in) :: problem
      type(lj_branch_type), intent(inout) :: branch
      integer, intent(in) :: by, stage, dir
      integer, intent(inout) :: i
      type(lj_path_type), intent(inout) :: path
      logical, intent(out) :: landed
      integer, intent(out) :: status
      integer :: land
      call record(path, stage, lj_path_jump_start, branch, i)
      call find_landing(problem, branch, by, i, dir, q_of(branch, by, i), land, status)
      landed = status == wa_ok .and. land /= 0
      if (.not. landed) return
      i = land
      call record(path, stage, lj_path_jump_end, branch, i)
   end subroutine jump

   !> Direction (+1 or -1 along the branch) in which q rises (sense = 1) or falls
   !> (sense = -1) from point i.
   pure integer function rising(branch, by, i, sense)
      type(lj_branch_type), intent(in) :: branch
      integer, intent(in) :: by, i, sense
      real(wp) :: d
      if (i < branch%n) then
         d = q_of(branch, by, i + 1) - q_of(branch, by, i)
      else
         d = q_of(branch, by, i) - q_of(branch, by, i - 1)
      end if
      rising = merge(1, -1, d*sense > 0.0_wp)
   end function rising

   pure logical function reached_full_contact(path, stage)
      type(lj_path_type), intent(in) :: path
      integer, intent(in) :: stage
      reached_full_contact = .false.
      if (path%n == 0) return
      reached_full_contact = path%stage(path%n) == stage .and. &
         path%event(path%n) == lj_path_full_contact_reached
   end function reached_full_contact

   pure subroutine fail(code, text, errmsg, status)
      integer, intent(in) :: code
      character(len=*), intent(in) :: text
      character(len=*), intent(inout), optional :: errmsg
      integer, intent(out), optional :: status
      integer :: st
      call set_error(code, text, st, errmsg)
      if (present(status)) status = st
   end subroutine fail

end module wa_bem_path
