!> Gap-controlled (mean-gap) approach and retraction along a traced branch, and the
!> energy lost per cycle W* = -oint P* dgbar* (doc/theory.md, "Gap control").
!>
!> The branch pieces are joined into one chain from the first interaction (MD: the
!> no-contact family; other models: the a* -> 0 end of the contact curve) to full
!> contact (a* = 1/2, gbar* = 0). Stability under gap control changes only where gbar*
!> is extremal along the chain (smooth turns, located by golden sections with the point
!> solver, and corners); the last stretch (to full contact) is stable, so stability is
!> the parity of the number of gbar* extrema between a state and full contact.
module wa_gappath
   use wa_kinds, only: wp, pi
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_negative_inf
   use wa_status, only: wa_ok, wa_numerical_error, wa_invalid_argument, set_error
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_no_contact, zone_inside, zone_whole_period, &
      zone_full_contact, model_md, model_dw
   use wa_models, only: model_roots, max_model_roots
   use wa_separation, only: state_mean_gap, dw_state_gbar, md_state_gbar
   use wa_md_nocontact, only: md_no_contact_state
   use wa_curve, only: curve_residual, curve_state, curve_variable, curve_weight, &
      curve_case2_load, curve_y_max
   use wa_branch, only: branch_type, trace_branch, event_switch, event_branch_end, &
      event_none, event_a_turn, event_jump_start, event_jump_end, event_full_contact_reached
   use wa_loadpath, only: path_type
   implicit none
   private

   public :: gap_path_type, gap_path, gap_path_from_branch, gap_law
   public :: gap_stage_approach, gap_stage_retraction
   public :: gap_event_jump_start, gap_event_jump_end, gap_event_full_contact_reached, &
      gap_event_full_contact_left, gap_event_touch, gap_event_contact_made, &
      gap_event_contact_lost, gap_event_interaction_lost
   !> (appended for gap_critical in wa_gapcritical)
   public :: gap_cycle_critical
   public :: load_jump_energies

   integer, parameter :: gap_stage_approach = 1, gap_stage_retraction = 2
   !> Event codes of a gap-controlled path (3-6 as in wa_branch)
   integer, parameter :: gap_event_jump_start = 3, gap_event_jump_end = 4, &
      gap_event_full_contact_reached = 5, gap_event_full_contact_left = 6, &
      gap_event_touch = 10, gap_event_contact_made = 11, gap_event_contact_lost = 12, &
      gap_event_interaction_lost = 13
   integer, parameter :: max_events = 64, max_jumps = 15
   !> Gauss-Legendre nodes per quadrature panel
   integer, parameter :: n_gauss = 16
   !> The a* -> 0 end of a contact curve that does not join a no-contact state
   real(wp), parameter :: a_limit = 1.0e-15_wp

   !> The events of one approach-retraction cycle under gap control, in order.
   type :: gap_path_type
      integer :: n = 0
      integer :: stage(max_events) = 0, event(max_events) = 0, zone_case(max_events) = 0
      real(wp) :: a_star(max_events) = 0.0_wp, c_star(max_events) = 0.0_wp, &
         p_star(max_events) = 0.0_wp, gbar(max_events) = 0.0_wp
      !> Energy lost per cycle W* = -oint P* dgbar* (units p* Delta) and W*/(pi alpha^2/2)
      real(wp) :: w_star = 0.0_wp, w_fraction = 0.0_wp
      !> gbar* where the surfaces first interact on approach (P* = 0 above it)
      real(wp) :: g_touch = 1.0_wp
   end type gap_path_type

   !> The branch as one chain; positions on it are s = i + t (t in [0, 1] of the
   !> parameter between points i and i+1: c* on no-contact stretches, else a*).
   type :: chain_type
      integer :: n = 0
      real(wp), allocatable :: a(:), c(:), p(:), g(:)
      !> curve variable y (wa_curve) of case-1 points of DW and MD, else 0
      real(wp), allocatable :: y(:)
      integer, allocatable :: zone(:), event(:)
      integer :: model = 0
      logical, allocatable :: extremum(:), stable_after(:)
      !> true when the chain's first point is the end of the P* = 0 states (MD)
      logical :: joined = .false.
      !> Traced points that the refinement of a gbar* extremum replaced (locate_extrema):
      !> their chain positions s (in the refined chain), P*, gbar* and a*. Such a point
      !> can be a fold of P* one node from the extremum (small alpha): the retraction
      !> passes it, so its P* counts for P_min (gap_cycle_critical).
      integer :: n_moved = 0
      real(wp), allocatable :: moved_s(:), moved_p(:), moved_g(:), moved_a(:)
      !> interval i reaches below the tracer's first point a* = a_start with no traced
      !> point inside (below_tracer)
      logical, allocatable :: untraced(:)
   end type chain_type

   !> The last case-1 solutions along a run of nodes (a panel's, in order): they predict
   !> the next curve variable y by extrapolation, so its bracket can be tight.
   type :: y_hint_type
      integer :: n = 0
      real(wp) :: x(3) = 0.0_wp, y(3) = 0.0_wp
      !> sign of dF/dy at the last one
      real(wp) :: slope = 1.0_wp
   end type y_hint_type

   !> One walked stretch of the chain
   type :: stretch_type
      real(wp) :: s1 = 0.0_wp, s2 = 0.0_wp
   end type stretch_type

   !> Gauss-Legendre nodes and weights on [-1, 1], the barycentric weights of the nodes
   !> and the differentiation matrix of the interpolating polynomial (d(j, l): weight of
   !> value l in the derivative at node j).
   type :: rule_type
      integer :: n = 0
      real(wp), allocatable :: x(:), w(:), bw(:), d(:, :)
      !> Legendre coefficients of the interpolant from the values at the nodes: c = leg f
      real(wp), allocatable :: leg(:, :)
   end type rule_type

   !> The chain under the walked stretches cut into pieces (between consecutive walked
   !> ends and the nodes where the parameter changes kind or direction: smooth in their
   !> variable, gbar* monotone), each covered adaptively by Gauss-Legendre panels that
   !> hold P* and gbar* at their nodes. Shared by W* (the integrals) and the gap law
   !> (the interpolants).
   type :: cover_type
      type(rule_type) :: rule
      integer :: n_pieces = 0, n_panels = 0
      !> piece k: chain positions s0 < s1, chain intervals i_lo..i_hi, its variable u
      !> (var: var_* codes, with anchor and side), panels
      !> first..last in order from s0 to s1, int P* dgbar* from s0 to s1, and P* = -Sigma0
      !> throughout (constant_load: no panels)
      real(wp), allocatable :: s0(:), s1(:), integral(:), anchor(:), side(:), u_start(:), &
         u_end(:)
      integer, allocatable :: i_lo(:), i_hi(:), first(:), last(:), var(:)
      logical, allocatable :: constant_load(:)
      !> panel j: [u0, u1] in its piece's variable, P* and gbar* at the nodes, gbar* at
      !> both ends (interpolated), int P* dgbar* from u0 to u1
      real(wp), allocatable :: u0(:), u1(:), pv(:, :), gv(:, :), g0(:), g1(:), pint(:)
   end type cover_type

   !> Accuracy asked of every panel's interpolants of P* and gbar*: the last Legendre
   !> coefficients relative to the largest
   real(wp), parameter :: tol_value = 1.0e-14_wp
   !> Bisections of a piece, at most
   integer, parameter :: max_depth = 48
   !> Tails of a panel below this share of its values that do not shrink when the panel
   !> is halved are the noise of the point solves (accepted: bisecting cannot help)
   real(wp), parameter :: noise_level = 1.0e-11_wp
   !> Chain intervals per first panel of a piece
   real(wp), parameter :: chain_per_panel = 16.0_wp
   !> Panels of one cover, at most (a bound on the work: typical covers need 10-60)
   integer, parameter :: max_panels = 4000
   !> The variable u of a piece: the chain parameter x (var_x); ln x where the piece
   !> reaches towards x = 0 (a* -> 0, c* -> 0: power-log behaviour; var_log). Where a piece
   !> in a* runs into a zone switch or an a* turn at a* = anchor (square-root behaviour
   !> in a* there): x = anchor + side u^2 if it ends there (var_root), else
   !> x = anchor + side e^u (var_log_distance), or x = anchor/(1 + e^-u) if it also
   !> reaches towards 0 (var_logit).
   integer, parameter :: var_x = 0, var_log = 1, var_root = 2, var_log_distance = 3, &
      var_logit = 4

contains

   !> Trace the branch, then follow approach and retraction under gap control.
   subroutine gap_path(model, params, path, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(gap_path_type), intent(out) :: path
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      call trace_branch(model, params, branch, status, errmsg)
      if (status /= wa_ok) return
      call gap_path_from_branch(model, params, branch, path, status, errmsg)
   end subroutine gap_path

   !> Approach from far apart to full contact and retraction, on a traced branch.
   subroutine gap_path_from_branch(model, params, branch, path, status, errmsg, nodes, splits)
      integer, intent(in) :: model
      !> Gauss-Legendre nodes per panel (default 12) and panels per chain interval
      !> (default 1): for checking the quadrature of W*
      integer, intent(in), optional :: nodes, splits
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(gap_path_type), intent(out) :: path
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(chain_type) :: ch
      type(stretch_type) :: walked(2*max_jumps + 4)
      type(cover_type) :: cov
      integer :: n_walked, n_approach, n_nodes, n_splits

      call walk_cycle(model, params, branch, ch, path, walked, n_walked, n_approach, &
         status, errmsg)
      if (status /= wa_ok) return
      n_nodes = n_gauss
      n_splits = 1
      if (present(nodes)) n_nodes = max(2, min(nodes, 64))
      if (present(splits)) n_splits = max(1, min(splits, 64))
      call build_cover(model, params, ch, walked(1:n_walked), n_nodes, n_splits, cov, status, &
         errmsg, net_only=.true.)
      if (status /= wa_ok) return
      call cycle_energy(params, cov, walked(1:n_walked), path, status, errmsg)
   end subroutine gap_path_from_branch

   !> The gap law: P* on approach and on retraction at each mean gap gbar(k) >= 0, and
   !> the slopes dP*/dgbar* (P* = 0 and slope 0 where the surfaces do not interact; at
   !> gbar* = 0, full contact, P* at a* -> 1/2 and slope -Infinity: dP*/dgbar* ~ -1/(1/2 - a*)^2
   !> there). P* and the slopes come from the polynomial interpolants of the panels that
   !> also give W* (doc/theory.md, "Gap control": ~1e-13 in P*, ~1e-10 in the slopes).
   !> w_star, w_fraction (optional): the energy lost per cycle, as gap_path gives it (the
   !> same panels: equal to the bit), at no extra cost.
   subroutine gap_law(model, params, gbar, p_approach, p_retract, dpdg_approach, &
      dpdg_retract, status, errmsg, w_star, w_fraction)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: gbar(:)
      real(wp), intent(out) :: p_approach(:), p_retract(:), dpdg_approach(:), dpdg_retract(:)
      real(wp), intent(out), optional :: w_star, w_fraction
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      type(chain_type) :: ch
      type(gap_path_type) :: path
      type(stretch_type) :: walked(2*max_jumps + 4)
      type(cover_type) :: cov
      integer :: n_walked, n_approach, k
      logical :: found

      p_approach = 0.0_wp; p_retract = 0.0_wp; dpdg_approach = 0.0_wp; dpdg_retract = 0.0_wp
      if (present(w_star)) w_star = 0.0_wp
      if (present(w_fraction)) w_fraction = 0.0_wp
      if (size(p_approach) /= size(gbar) .or. size(p_retract) /= size(gbar) .or. &
         size(dpdg_approach) /= size(gbar) .or. size(dpdg_retract) /= size(gbar)) then
         call set_error(wa_invalid_argument, "gap_law: the output arrays must have the "// &
            "size of gbar", status, errmsg)
         return
      end if
      do k = 1, size(gbar)
         if (.not. (ieee_is_finite(gbar(k)) .and. gbar(k) >= 0.0_wp)) then
            call set_error(wa_invalid_argument, "gbar: must be finite and >= 0 (the mean "// &
               "gap over the wave amplitude)", status, errmsg)
            return
         end if
      end do
      call trace_branch(model, params, branch, status, errmsg)
      if (status /= wa_ok) return
      call walk_cycle(model, params, branch, ch, path, walked, n_walked, n_approach, &
         status, errmsg)
      if (status /= wa_ok) return
      call build_cover(model, params, ch, walked(1:n_walked), n_gauss, 1, cov, status, errmsg)
      if (status /= wa_ok) return
      if (present(w_star) .or. present(w_fraction)) then
         ! the pieces walked both ways add m = 0: the sum is gap_path's
         call cycle_energy(params, cov, walked(1:n_walked), path, status, errmsg)
         if (status /= wa_ok) return
         if (present(w_star)) w_star = path%w_star
         if (present(w_fraction)) w_fraction = path%w_fraction
      end if
      do k = 1, size(gbar)
         if (gbar(k) == 0.0_wp) then               ! full contact: P* ~ P_end - sqrt(2 g)
            p_approach(k) = ch%p(ch%n); p_retract(k) = ch%p(ch%n)
            dpdg_approach(k) = ieee_value(1.0_wp, ieee_negative_inf)
            dpdg_retract(k) = dpdg_approach(k)
            cycle
         end if
         call law_on(cov, params, ch, walked(1:n_approach), gbar(k), p_approach(k), &
            dpdg_approach(k), found)
         call law_on(cov, params, ch, walked(n_approach + 1:n_walked), gbar(k), p_retract(k), &
            dpdg_retract(k), found)
      end do
   end subroutine gap_law

   ! ------------------------------------------------------------------ chain

   !> Join the branch pieces end to start (MD: the no-contact piece from the first
   !> interaction, then the contact curve) until a piece reaches a* = 1/2.
   subroutine build_chain(model, params, branch, ch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(chain_type), intent(out) :: ch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, allocatable :: first(:), last(:)
      logical, allocatable :: used(:)
      integer :: i, k, n_pieces, cur, next
      real(wp) :: d_best, dc, dp
      type(state_type) :: s

      status = wa_ok
      allocate (first(branch%n), last(branch%n))
      n_pieces = 0
      i = 1
      do while (i <= branch%n)                       ! pieces: event 8 at both ends
         n_pieces = n_pieces + 1
         first(n_pieces) = i
         k = i + 1
         do while (k < branch%n)
            if (branch%event(k) == event_branch_end) exit
            k = k + 1
         end do
         last(n_pieces) = min(k, branch%n)
         i = last(n_pieces) + 1
      end do
      allocate (used(n_pieces))
      used = .false.
      allocate (ch%a(branch%n + 1), ch%c(branch%n + 1), ch%p(branch%n + 1), &
         ch%g(branch%n + 1), ch%zone(branch%n + 1), ch%event(branch%n + 1))
      cur = 1
      ch%joined = branch%zone_case(1) == zone_no_contact
      if (.not. ch%joined) then                      ! the limit a* -> 0 of the first piece
         call solve_at_a(model, params, a_limit, branch%c_star(1), -1, s, status, errmsg)
         if (status /= wa_ok) return
         call push(ch, s%a_star, s%c_star, s%p_star, s%gbar, s%zone_case, 0)
      end if
      do k = 1, n_pieces
         used(cur) = .true.
         do i = first(cur), last(cur)
            call push(ch, branch%a_star(i), branch%c_star(i), branch%p_star(i), &
               branch%gbar(i), branch%zone_case(i), branch%event(i))
         end do
         if (branch%a_star(last(cur)) >= 0.5_wp - 1.0e-8_wp) exit
         ! the piece starting nearest the end of this one (a joint at a* -> 0 matches
         ! to within what a_start = 1e-6 moves c* and P*: relative 5 %)
         next = 0
         d_best = huge(1.0_wp)
         do i = 1, n_pieces
            if (used(i)) cycle
            dc = abs(branch%c_star(first(i)) - branch%c_star(last(cur)))
            dp = abs(branch%p_star(first(i)) - branch%p_star(last(cur)))
            if (branch%zone_case(last(cur)) == zone_no_contact) then
               ! a closed crest joins the contact curve's a* -> 0 end (at large mu c* there
               ! can be below a_start: nearest c* among the contact pieces)
               if (branch%zone_case(first(i)) == zone_no_contact) cycle
            else if (dc > 0.05_wp*branch%c_star(last(cur)) + 1.0e-6_wp .or. &
               dp > 0.05_wp*abs(branch%p_star(last(cur))) + 1.0e-6_wp) then
               cycle
            end if
            if (dc + dp < d_best) then
               d_best = dc + dp
               next = i
            end if
         end do
         if (next == 0) then
            call set_error(wa_numerical_error, "gap_path: the branch pieces do not join "// &
               "into one curve from the first interaction to full contact", status, errmsg)
            return
         end if
         cur = next
      end do
      if (ch%a(ch%n) < 0.5_wp - 1.0e-8_wp) then
         call set_error(wa_numerical_error, "gap_path: the joined branch does not reach "// &
            "full contact", status, errmsg)
         return
      end if
      allocate (ch%extremum(ch%n), ch%stable_after(ch%n), ch%y(ch%n))
      ch%model = model
      ch%y = 0.0_wp
      if (model == model_dw .or. model == model_md) then
         do i = 1, ch%n
            if (ch%zone(i) == zone_inside .and. params%sigma0 > 0.0_wp) &
               ch%y(i) = curve_variable(model, chain_state(ch, i))
         end do
      end if
      ch%extremum = .false.
      ch%stable_after = .false.
      ! the a_limit extension of a contact curve, or the joint between the closure of MD's
      ! no-contact states (a* = 0) and the contact curve
      allocate (ch%untraced(ch%n))
      ch%untraced = .false.
      do i = 1, ch%n - 1
         ch%untraced(i) = (i == 1 .and. .not. ch%joined) .or. (ch%zone(i) == zone_no_contact &
            .and. ch%a(i) == 0.0_wp .and. ch%zone(i + 1) == zone_inside) .or. &
            (ch%zone(i + 1) == zone_no_contact .and. ch%a(i + 1) == 0.0_wp .and. &
            ch%zone(i) == zone_inside)
      end do
   contains
      subroutine push(ch, a, c, p, g, zone, event)
         type(chain_type), intent(inout) :: ch
         real(wp), intent(in) :: a, c, p, g
         integer, intent(in) :: zone, event
         if (ch%n > 0) then                          ! a joint repeats a state
            if (ch%a(ch%n) == a .and. ch%c(ch%n) == c .and. ch%g(ch%n) == g .and. &
               ch%zone(ch%n) == zone) return
         end if
         ch%n = ch%n + 1
         ch%a(ch%n) = a; ch%c(ch%n) = c; ch%p(ch%n) = p; ch%g(ch%n) = g
         ch%zone(ch%n) = zone; ch%event(ch%n) = event
      end subroutine push
   end subroutine build_chain

   !> Case-1 intervals that end (or start) at a switch to c* = 1/2 with a* nearly constant
   !> (a fold of P* within round-off of the switch: the tracer's step is small in
   !> (a*, w y), while c* runs to 1/2): gbar* can turn twice inside such an interval, a
   !> pair of extrema that no chain point shows (MD, small alpha: the gap cycle's inner
   !> jumps then came and went with mu). gbar* is sampled at n_samples curve variables
   !> y across the interval (y = y_max at the switch) and the samples where it turns join
   !> the chain, so that locate_extrema finds and refines the pair.
   subroutine sample_switch_intervals(model, params, ch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(chain_type), intent(inout) :: ch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, parameter :: n_samples = 8
      type(state_type) :: st(0:n_samples + 1)
      real(wp) :: ys(0:n_samples + 1), y0, y1
      integer :: i, k, n_turn, turn(n_samples), j_in
      logical :: steep

      status = wa_ok
      if (.not. (model == model_dw .or. model == model_md) .or. params%sigma0 <= 0.0_wp) &
         return
      i = 1
      do while (i < ch%n)
         j_in = 0                                ! the case-1 end of the interval
         if (ch%event(i + 1) == event_switch .and. ch%zone(i) == zone_inside) then
            j_in = i
         else if (ch%event(i) == event_switch .and. ch%zone(i + 1) == zone_inside) then
            j_in = i + 1
         end if
         steep = .false.
         if (j_in > 0) steep = abs(ch%a(i + 1) - ch%a(i)) < &
            curve_weight(model)*abs(curve_y_max - ch%y(j_in))
         if (.not. steep) then
            i = i + 1
            cycle
         end if
         y0 = merge(ch%y(i), curve_y_max, j_in == i)
         y1 = merge(ch%y(i + 1), curve_y_max, j_in == i + 1)
         st(0) = chain_state(ch, i)
         st(n_samples + 1) = chain_state(ch, i + 1)
         n_turn = 0
         do k = 1, n_samples
            ys(k) = y0 + (y1 - y0)*real(k, wp)/real(n_samples + 1, wp)
            call solve_at_y(model, params, ch, i, ys(k), st(k), status)
            if (status /= wa_ok) exit
         end do
         if (status /= wa_ok) then        ! the samples are a bonus: the interval stays
            status = wa_ok                ! as traced
            i = i + 1
            cycle
         end if
         do k = 1, n_samples
            if ((st(k)%gbar - st(k - 1)%gbar)*(st(k + 1)%gbar - st(k)%gbar) < 0.0_wp) then
               n_turn = n_turn + 1
               turn(n_turn) = k
            end if
         end do
         do k = n_turn, 1, -1                    ! insert after i, last first
            call chain_insert(ch, i, st(turn(k)), ys(turn(k)))
         end do
         i = i + n_turn + 1
      end do
   end subroutine sample_switch_intervals

   !> Insert the case-1 state sx (curve variable yx) into the chain after point at.
   pure subroutine chain_insert(ch, at, sx, yx)
      type(chain_type), intent(inout) :: ch
      integer, intent(in) :: at
      type(state_type), intent(in) :: sx
      real(wp), intent(in) :: yx
      ch%a = [ch%a(:at), sx%a_star, ch%a(at + 1:)]
      ch%c = [ch%c(:at), sx%c_star, ch%c(at + 1:)]
      ch%p = [ch%p(:at), sx%p_star, ch%p(at + 1:)]
      ch%g = [ch%g(:at), sx%gbar, ch%g(at + 1:)]
      ch%y = [ch%y(:at), yx, ch%y(at + 1:)]
      ch%zone = [ch%zone(:at), zone_inside, ch%zone(at + 1:)]
      ch%event = [ch%event(:at), event_none, ch%event(at + 1:)]
      ch%extremum = [ch%extremum(:at), .false., ch%extremum(at + 1:)]
      ch%stable_after = [ch%stable_after(:at), .false., ch%stable_after(at + 1:)]
      ch%untraced = [ch%untraced(:at), ch%untraced(at), ch%untraced(at + 1:)]
      ch%n = ch%n + 1
   end subroutine chain_insert

   !> The chain interval below the tracer's first point a* = a_start (below_tracer: from
   !> a* -> 0 to a_start, no traced point inside) can hold a turn of gbar* (gbar* -
   !> gbar*(0) ~ a*^2 (k1 ln a* + k2), as P*): at alpha below ~4e-8 the retraction's
   !> jump-out maximum lies there, and the walk went on to a* -> 0 past it (contact
   !> lost after the most tensile state, g_P_min > g_interaction_lost). gbar* is sampled
   !> at a* = a_start 10^(-k/2) down to where it is flat to round-off (or to 1e-9 of
   !> a_start), and where it turns (by more than 1e-13 of gbar* on both sides) the turn
   !> and its neighbouring samples join the chain, for locate_extrema to refine. Where
   !> no turn is found the chain stays as traced.
   subroutine sample_floor_intervals(model, params, ch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(chain_type), intent(inout) :: ch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer, parameter :: n_max = 18
      type(state_type) :: st(0:n_max + 1)
      real(wp) :: x, t, noise, d1, d2
      integer :: i, k, n, lo_end, hi_end, k_turn, k0, k1
      logical :: done

      status = wa_ok
      if (.not. (model == model_dw .or. model == model_md) .or. params%sigma0 <= 0.0_wp) &
         return
      i = 1
      do while (i < ch%n)
         if (.not. below_tracer(ch, i)) then
            i = i + 1
            cycle
         end if
         lo_end = merge(i, i + 1, ch%a(i) < ch%a(i + 1))
         hi_end = 2*i + 1 - lo_end
         ! the round-off of gbar* of the point solves (MD's mean gap by quadrature: ~1e-14,
         ! and its turns at that level flickered the gap map's mechanisms at alpha = 3)
         noise = 1.0e-13_wp*max(abs(ch%g(i)), abs(ch%g(i + 1)))
         st(0) = chain_state(ch, hi_end)         ! samples by falling a*
         n = 0
         do k = 1, n_max
            x = ch%a(hi_end)*10.0_wp**(-0.5_wp*real(k, wp))
            if (x <= ch%a(lo_end)) exit
            t = (x - ch%a(i))/(ch%a(i + 1) - ch%a(i))
            call local_state(model, params, ch, i, x, t, st(k), done, status, errmsg)
            if (.not. done .and. status == wa_ok) call solve_at_a(model, params, x, &
               ch%c(i) + t*(ch%c(i + 1) - ch%c(i)), zone_inside, st(k), status, errmsg)
            if (status /= wa_ok .or. st(k)%zone_case /= zone_inside) exit
            n = k
            if (abs(st(k)%gbar - ch%g(lo_end)) <= noise) exit    ! flat from here down
         end do
         status = wa_ok                          ! the samples are a bonus
         st(n + 1) = chain_state(ch, lo_end)
         k_turn = 0
         do k = 1, n
            d1 = st(k)%gbar - st(k - 1)%gbar
            d2 = st(k + 1)%gbar - st(k)%gbar
            if (d1*d2 < 0.0_wp .and. min(abs(d1), abs(d2)) > noise) then
               k_turn = k
               exit
            end if
         end do
         if (k_turn == 0) then
            i = i + 1
            cycle
         end if
         k0 = max(1, k_turn - 1); k1 = min(n, k_turn + 1)
         ! insert after i in the chain's order (a* rising from i to i + 1 or falling)
         do k = merge(k0, k1, lo_end == i), merge(k1, k0, lo_end == i), merge(1, -1, lo_end == i)
            call chain_insert(ch, i, st(k), curve_variable(model, st(k)))
         end do
         i = i + (k1 - k0 + 1) + 1
      end do
   end subroutine sample_floor_intervals

   !> Mark the extrema of gbar* along the chain (refined to full precision where smooth)
   !> and the stability of each stretch: stable on the last, flipped at each extremum.
   !> A run of equal gbar* (a plateau: at alpha ~ 1e-12 the whole no-contact piece lies
   !> within a few ulps of 1) is an extremum, at its last point, where gbar* rises into it
   !> and falls out of it (or the reverse); else the parity of the stability is lost.
   subroutine locate_extrema(model, params, ch, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(chain_type), intent(inout) :: ch
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer :: i
      logical :: stable
      type(state_type) :: s, traced
      real(wp) :: d_before

      status = wa_ok
      allocate (ch%moved_s(ch%n), ch%moved_p(ch%n), ch%moved_g(ch%n), ch%moved_a(ch%n))
      ch%n_moved = 0
      d_before = 0.0_wp                    ! the last nonzero step of gbar* up to point i
      do i = 2, ch%n - 1
         if (ch%g(i) /= ch%g(i - 1)) d_before = ch%g(i) - ch%g(i - 1)
         if (d_before*(ch%g(i + 1) - ch%g(i)) >= 0.0_wp) cycle
         ch%extremum(i) = .true.
         if (ch%event(i) == event_switch) cycle      ! a corner: exact already
         if (param_kind(ch, i - 1) == param_kind(ch, i) .and. &
            (param(ch, i - 1, 1.0_wp) - param(ch, i - 1, 0.0_wp))* &
            (param(ch, i, 1.0_wp) - param(ch, i, 0.0_wp)) <= 0.0_wp) cycle
         call refine_extremum(model, params, ch, i, s, status, errmsg)
         if (status /= wa_ok .and. param_kind(ch, i - 1) /= param_kind(ch, i)) then
            status = wa_ok                ! refining across the change of parameter is a
            s = chain_state(ch, i)        ! bonus: the traced point stands
         end if
         if (status /= wa_ok) return
         traced = chain_state(ch, i)
         ch%a(i) = s%a_star; ch%c(i) = s%c_star; ch%p(i) = s%p_star; ch%g(i) = s%gbar
         if (ch%y(i) /= 0.0_wp) ch%y(i) = curve_variable(model, chain_state(ch, i))
         if (traced%a_star /= s%a_star .or. traced%c_star /= s%c_star) then
            ch%n_moved = ch%n_moved + 1
            ch%moved_s(ch%n_moved) = position_near(model, ch, i, traced)
            ch%moved_p(ch%n_moved) = traced%p_star
            ch%moved_g(ch%n_moved) = traced%gbar
            ch%moved_a(ch%n_moved) = traced%a_star
         end if
      end do
      stable = .true.
      do i = ch%n - 1, 1, -1
         ch%stable_after(i) = stable
         if (ch%extremum(i)) stable = .not. stable
      end do
   end subroutine locate_extrema

   !> The chain position of state st on one of the intervals next to point i (i-1 or
   !> i): where the interval's parameter takes st's value (clamped to the nearer one).
   pure real(wp) function position_near(model, ch, i, st) result(pos)
      integer, intent(in) :: model, i
      type(chain_type), intent(in) :: ch
      type(state_type), intent(in) :: st
      real(wp) :: x, x0, x1, t, t_best, miss, miss_best
      integer :: k, k_best
      k_best = i; t_best = 0.0_wp; miss_best = huge(1.0_wp)
      do k = i, i - 1, -1
         select case (param_kind(ch, k))
         case (1)
            x = st%c_star
         case (2)
            x = st%gbar
         case (3)
            x = curve_variable(model, st)
         case default
            x = st%a_star
         end select
         x0 = param(ch, k, 0.0_wp); x1 = param(ch, k, 1.0_wp)
         t = 0.5_wp
         if (x1 /= x0) t = (x - x0)/(x1 - x0)
         miss = max(-t, t - 1.0_wp, 0.0_wp)
         if (miss < miss_best) then
            miss_best = miss; k_best = k; t_best = min(max(t, 0.0_wp), 1.0_wp)
         end if
      end do
      pos = real(k_best - 1, wp) + t_best
   end function position_near

   !> The extremum of gbar* over the parameter between points i-1 and i+1 (Brent's
   !> minimisation, then a parabola-vertex step), or over a* when the two intervals use
   !> different parameters (a* and the curve variable y, where a* turns steep) and a* is
   !> monotone across them.
   subroutine refine_extremum(model, params, ch, i, s, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: lo, hi, sgn, lo0, hi0, x_best
      logical :: in_a

      status = wa_ok
      s = chain_state(ch, i)
      sgn = merge(1.0_wp, -1.0_wp, ch%g(i) > ch%g(i + 1))    ! +1: maximum
      in_a = param_kind(ch, i - 1) /= param_kind(ch, i)
      if (in_a) then                   ! only within case 1, a* monotone across both
         ! (a neighbour may be the closure of the MD no-contact states, a* = 0: the
         ! interval to it is case 1 in a*, below the tracer's first point a* = 1e-6,
         ! where the maximum the retraction jumps from can lie)
         if (.not. ((ch%a(i) - ch%a(i - 1))*(ch%a(i + 1) - ch%a(i)) > 0.0_wp .and. &
            ch%zone(i) == zone_inside .and. closure_or_inside(i - 1) .and. &
            closure_or_inside(i + 1))) return
         lo = ch%a(i - 1); hi = ch%a(i + 1)
      else
         lo = param(ch, i - 1, 0.0_wp); hi = param(ch, i, 1.0_wp)
      end if
      lo0 = lo; hi0 = hi
      call brent_minimum(min(lo, hi), max(lo, hi), x_best)
      if (status /= wa_ok) return
      call vertex_refinement(x_best)
      if (status /= wa_ok) return
      if (-sgn*s%gbar > -sgn*ch%g(i)) s = chain_state(ch, i)    ! never worse than the point
   contains
      pure logical function closure_or_inside(j)
         integer, intent(in) :: j
         closure_or_inside = ch%zone(j) == zone_inside .or. &
            (ch%zone(j) == zone_no_contact .and. ch%a(j) == 0.0_wp)
      end function closure_or_inside

      !> Brent's minimisation of -sgn gbar* over [a, b] (golden sections and parabolic
      !> steps) to 1e-9 of the bracket, x to ~sqrt(eps) of it in any case (gbar* is flat
      !> there): the vertex refinement below does the rest. s: the state at x.
      subroutine brent_minimum(a_in, b_in, x)
         real(wp), intent(in) :: a_in, b_in
         real(wp), intent(out) :: x
         real(wp), parameter :: c = 0.3819660112501051518_wp
         real(wp) :: a, b, v, w, fv, fw, fx, d, e, m, tol, t2, pp, q, rr, u, fu
         type(state_type) :: su
         integer :: it
         a = a_in; b = b_in
         x = a + c*(b - a); v = x; w = x
         call solve(x, s)
         if (status /= wa_ok) return
         fx = -sgn*s%gbar; fv = fx; fw = fx
         d = 0.0_wp; e = 0.0_wp
         do it = 1, 100
            m = 0.5_wp*(a + b)
            tol = 1.0e-9_wp*abs(b_in - a_in) + 1.0e-300_wp
            t2 = 2.0_wp*tol
            if (abs(x - m) <= t2 - 0.5_wp*(b - a)) exit
            pp = 0.0_wp; q = 0.0_wp; rr = 0.0_wp
            if (abs(e) > tol) then                   ! a parabola through x, w, v
               rr = (x - w)*(fx - fv)
               q = (x - v)*(fx - fw)
               pp = (x - v)*q - (x - w)*rr
               q = 2.0_wp*(q - rr)
               if (q > 0.0_wp) then
                  pp = -pp
               else
                  q = -q
               end if
               rr = e
               e = d
            end if
            if (abs(pp) < abs(0.5_wp*q*rr) .and. pp > q*(a - x) .and. pp < q*(b - x)) then
               d = pp/q
               u = x + d
               if (u - a < t2 .or. b - u < t2) d = sign(tol, m - x)
            else                                     ! a golden section
               e = merge(b - x, a - x, x < m)
               d = c*e
            end if
            u = x + merge(d, sign(tol, d), abs(d) >= tol)
            call solve(u, su)
            if (status /= wa_ok) return
            fu = -sgn*su%gbar
            if (fu <= fx) then
               if (u < x) then
                  b = x
               else
                  a = x
               end if
               v = w; fv = fw; w = x; fw = fx; x = u; fx = fu; s = su
            else
               if (u < x) then
                  a = u
               else
                  b = u
               end if
               if (fu <= fw .or. w == x) then
                  v = w; fv = fw; w = u; fw = fu
               else if (fu <= fv .or. v == x .or. v == w) then
                  v = u; fv = fu
               end if
            end if
         end do
      end subroutine brent_minimum

      !> The minimisation leaves x to ~sqrt(eps) of the bracket (gbar* is flat there):
      !> the vertex of the parabola through x0 and x0 +- d, with d = 1e-3 of the bracket,
      !> places it to ~1e-9 of the bracket (the noise of gbar* over g'' d); repeated with
      !> 2d and extrapolated (Richardson) to remove the d^2 bias of the cubic term. Kept
      !> only where both parabolas open the right way and their vertices lie within d.
      !> (The adhesion map's jump-out boundaries follow a* of a maximum of gbar*: to 1e-8
      !> in mu they need it to ~1e-8.)
      subroutine vertex_refinement(x0)
         real(wp), intent(in) :: x0
         real(wp) :: d, v1, v2, xv
         type(state_type) :: sv
         logical :: ok1, ok2
         d = 1.0e-3_wp*abs(hi0 - lo0)
         if (x0 - 2.0_wp*d < min(lo0, hi0) .or. x0 + 2.0_wp*d > max(lo0, hi0)) return
         call vertex(x0, d, v1, ok1)
         if (status /= wa_ok .or. .not. ok1) return
         call vertex(x0, 2.0_wp*d, v2, ok2)
         if (status /= wa_ok .or. .not. ok2) return
         xv = (4.0_wp*v1 - v2)/3.0_wp
         if (abs(xv - x0) > d) return
         call solve(xv, sv)
         if (status /= wa_ok) return
         s = sv
      end subroutine vertex_refinement

      !> The vertex v of the parabola through gbar* at x0 - h, x0 (the state s), x0 + h
      subroutine vertex(x0, h, v, ok)
         real(wp), intent(in) :: x0, h
         real(wp), intent(out) :: v
         logical, intent(out) :: ok
         type(state_type) :: sm, sp
         real(wp) :: den
         ok = .false.
         v = x0
         call solve(x0 - h, sm)
         if (status /= wa_ok) return
         call solve(x0 + h, sp)
         if (status /= wa_ok) return
         den = sp%gbar - 2.0_wp*s%gbar + sm%gbar
         if (.not. (sgn*den < 0.0_wp)) return
         v = x0 - h*(sp%gbar - sm%gbar)/(2.0_wp*den)
         ok = abs(v - x0) <= h
      end subroutine vertex

      !> The state at x on the interval (i - 1 or i) that holds it, guided by its data
      subroutine solve(x, st)
         real(wp), intent(in) :: x
         type(state_type), intent(out) :: st
         integer :: k
         real(wp) :: t
         logical :: done
         k = i
         if (in_a) then
            if ((x - ch%a(i - 1))*(x - ch%a(i)) <= 0.0_wp) k = i - 1
            t = (x - ch%a(k))/(ch%a(k + 1) - ch%a(k))
            call local_state(model, params, ch, k, x, t, st, done, status, errmsg)
            if (done .or. status /= wa_ok) return
            call solve_at_a(model, params, x, ch%c(k) + t*(ch%c(k + 1) - ch%c(k)), &
               zone_inside, st, status, errmsg)
         else
            if ((x - param(ch, i - 1, 0.0_wp))*(x - param(ch, i - 1, 1.0_wp)) <= 0.0_wp) &
               k = i - 1
            call state_at_param(model, params, ch, k, x, st, status, errmsg)
         end if
      end subroutine solve
   end subroutine refine_extremum

   ! -------------------------------------------------------------- the walk

   !> Approach (decreasing gbar* from far apart) or retraction (increasing from full
   !> contact), along stable stretches, jumping at constant gbar* at each turn.
   !> The chain of the traced branch with its gbar* extrema, and the approach and the
   !> retraction walked on it: walked(1:n_approach) approach, then the retraction up to
   !> n_walked (shared by gap_path and gap_law).
   subroutine walk_cycle(model, params, branch, ch, path, walked, n_walked, n_approach, &
         status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(chain_type), intent(out) :: ch
      type(gap_path_type), intent(inout) :: path
      type(stretch_type), intent(inout) :: walked(:)
      integer, intent(out) :: n_walked, n_approach
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      n_walked = 0
      n_approach = 0
      call build_chain(model, params, branch, ch, status, errmsg)
      if (status /= wa_ok) return
      path%g_touch = 1.0_wp
      if (ch%joined) path%g_touch = ch%g(1)
      call sample_switch_intervals(model, params, ch, status, errmsg)
      if (status /= wa_ok) return
      call sample_floor_intervals(model, params, ch, status, errmsg)
      if (status /= wa_ok) return
      call locate_extrema(model, params, ch, status, errmsg)
      if (status /= wa_ok) return
      call walk(model, params, ch, path, gap_stage_approach, walked, n_walked, status, errmsg)
      if (status /= wa_ok) return
      n_approach = n_walked
      call walk(model, params, ch, path, gap_stage_retraction, walked, n_walked, status, errmsg)
   end subroutine walk_cycle

   subroutine walk(model, params, ch, path, stage, walked, n_walked, status, errmsg)
      integer, intent(in) :: model, stage
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      type(gap_path_type), intent(inout) :: path
      type(stretch_type), intent(inout) :: walked(:)
      integer, intent(inout) :: n_walked
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: s_pos, s_end, s_from, g
      integer :: jumps, i, seg_lo, seg_hi, dir
      logical :: far
      type(state_type) :: st

      status = wa_ok
      if (stage == gap_stage_approach) then
         g = path%g_touch
         call add_far(path, stage, gap_event_touch, g)
         far = .true.
         s_pos = -1.0_wp
      else
         s_pos = real(ch%n - 1, wp)
         call add(path, stage, gap_event_full_contact_left, chain_state(ch, ch%n))
         far = .false.
      end if
      do jumps = 1, max_jumps + 1
         if (far) then                                ! land from the P* = 0 states
            if (.not. ch%joined .and. ch%stable_after(1) .and. abs(g - ch%g(1)) <= 1.0e-9_wp) then
               s_pos = 0.0_wp                         ! the contact curve starts at the touch
            else
               call land(model, params, ch, stage, -1.0_wp, g, s_pos, status, errmsg)
               if (status /= wa_ok) return
            end if
            if (s_pos /= 0.0_wp) then
               call add_far(path, stage, gap_event_jump_start, g)
               call add_at(model, params, ch, path, stage, gap_event_jump_end, s_pos, status, &
                  errmsg, g)
               if (status /= wa_ok) return
            end if
            far = .false.
         end if
         ! the stable stretch holding s_pos, and the direction of falling/rising gbar
         i = min(int(s_pos), ch%n - 2) + 1
         seg_lo = i; seg_hi = i + 1
         do while (seg_lo > 1)
            if (ch%extremum(seg_lo)) exit
            seg_lo = seg_lo - 1
         end do
         do while (seg_hi < ch%n)
            if (ch%extremum(seg_hi)) exit
            seg_hi = seg_hi + 1
         end do
         if ((ch%g(seg_hi) < ch%g(seg_lo)) .eqv. (stage == gap_stage_approach)) then
            dir = 1; s_end = real(seg_hi - 1, wp)
         else
            dir = -1; s_end = real(seg_lo - 1, wp)
         end if
         n_walked = n_walked + 1
         walked(n_walked) = stretch_type(s_pos, s_end)
         call contact_events(ch, path, stage, s_pos, s_end)
         s_pos = s_end
         i = nint(s_end) + 1                          ! chain point reached
         if (i == ch%n) then
            call add(path, stage, gap_event_full_contact_reached, chain_state(ch, i))
            return
         end if
         g = ch%g(i)
         if (stage == gap_stage_retraction .and. i == 1 .and. .not. ch%extremum(1)) then
            if (ch%joined) then                       ! the P* = 0 end of the MD chain
               call add_far(path, stage, gap_event_interaction_lost, g)
            else                                      ! a* -> 0: contact lost, P* jumps to 0
               call add(path, stage, gap_event_contact_lost, chain_state(ch, 1))
               call add_far(path, stage, gap_event_jump_end, g)
               call add_far(path, stage, gap_event_interaction_lost, g)
            end if
            return
         end if
         call add(path, stage, gap_event_jump_start, chain_state(ch, i))
         s_from = s_pos
         call land(model, params, ch, stage, s_from, g, s_pos, status, errmsg)
         if (status /= wa_ok) return
         if (s_pos < 0.0_wp) then                     ! onto the P* = 0 states
            if (stage == gap_stage_approach) then
               call set_error(wa_numerical_error, "gap_path: no stable state to land on "// &
                  "during the approach", status, errmsg)
               return
            end if
            call add_far(path, stage, gap_event_jump_end, g)
            call add_far(path, stage, gap_event_interaction_lost, g)
            return
         end if
         call add_at(model, params, ch, path, stage, gap_event_jump_end, s_pos, status, errmsg, g)
         if (status /= wa_ok) return
      end do
      call set_error(wa_numerical_error, "gap_path: more jumps than expected", status, errmsg)
   end subroutine walk

   !> Contact made (approach) or lost (retraction) where a walked stretch crosses the
   !> joint between the MD no-contact states and the contact curve.
   subroutine contact_events(ch, path, stage, s1, s2)
      integer, intent(in) :: stage
      type(chain_type), intent(in) :: ch
      type(gap_path_type), intent(inout) :: path
      real(wp), intent(in) :: s1, s2
      integer :: i
      do i = 1, ch%n - 1
         if (ch%zone(i) /= zone_no_contact .or. ch%zone(i + 1) == zone_no_contact) cycle
         if (real(i - 1, wp) >= min(s1, s2) .and. real(i - 1, wp) <= max(s1, s2) .and. &
            s1 /= s2) call add(path, stage, merge(gap_event_contact_made, &
            gap_event_contact_lost, stage == gap_stage_approach), chain_state(ch, i))
      end do
   end subroutine contact_events

   !> The stable state with gbar* = g nearest to s_from along the chain: ahead of it on
   !> approach, behind it on retraction (else anywhere); s_to = -1: the P* = 0 states.
   subroutine land(model, params, ch, stage, s_from, g, s_to, status, errmsg)
      integer, intent(in) :: model, stage
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: s_from, g
      real(wp), intent(out) :: s_to
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      integer :: i, best, pass
      real(wp) :: glo, ghi

      status = wa_ok
      s_to = -1.0_wp
      best = 0
      do pass = 1, 2
         if (stage == gap_stage_approach) then
            do i = 1, ch%n - 1
               if (candidate(i, pass)) then
                  best = i; exit
               end if
            end do
         else
            if (pass == 2 .and. g >= merge(ch%g(1), 1.0_wp, ch%joined)) return   ! far apart
            do i = ch%n - 1, 1, -1
               if (candidate(i, pass)) then
                  best = i; exit
               end if
            end do
         end if
         if (best > 0) exit
      end do
      if (best == 0) then
         call set_error(wa_numerical_error, "gap_path: no stable state to land on", status, &
            errmsg)
         return
      end if
      glo = ch%g(best); ghi = ch%g(best + 1)
      if (g == glo) then
         s_to = real(best - 1, wp)
      else if (g == ghi) then
         s_to = real(best, wp)
      else
         call solve_gbar(model, params, ch, best, g, s_to, status, errmsg)
      end if
   contains
      logical function candidate(i, pass)
         integer, intent(in) :: i, pass
         real(wp) :: s
         candidate = .false.
         if (.not. ch%stable_after(i)) return
         if (.not. (g >= min(ch%g(i), ch%g(i + 1)) .and. g <= max(ch%g(i), ch%g(i + 1)))) return
         s = real(i - 1, wp)
         if (pass == 1) then
            if (stage == gap_stage_approach .and. s + 1.0_wp <= s_from) return
            if (stage == gap_stage_retraction .and. s >= s_from) return
            ! not on the stretch just left (it ends at the turn)
            if (s_from >= 0.0_wp) then
               if (same_stretch(ch, i, nint(s_from) + 1)) return
            end if
         end if
         candidate = .true.
      end function candidate
   end subroutine land

   !> Does chain interval i belong to a stretch ending at the extremum point j?
   pure logical function same_stretch(ch, i, j)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i, j
      integer :: k
      same_stretch = .false.
      if (i == j .or. i == j - 1) then
         same_stretch = .true.
         return
      end if
      if (i > j) then
         do k = j + 1, i
            if (ch%extremum(k)) return
         end do
      else
         do k = i + 1, j - 1
            if (ch%extremum(k)) return
         end do
      end if
      same_stretch = .true.
   end function same_stretch

   !> The position in chain interval i where gbar* = g (Brent on the parameter).
   subroutine solve_gbar(model, params, ch, i, g, s_to, status, errmsg)
      use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
      integer, intent(in) :: model, i
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: g
      real(wp), intent(out) :: s_to
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      type(state_type) :: s
      real(wp) :: x, x0, x1
      logical :: done
      integer :: iter
      x0 = param(ch, i, 0.0_wp); x1 = param(ch, i, 1.0_wp)
      call brent_init(solver, x0, ch%g(i) - g, x1, ch%g(i + 1) - g, &
         1.0e-15_wp*max(abs(x0), abs(x1)))
      status = wa_ok
      do iter = 1, 200
         call brent_propose(solver, x, done)
         if (done) exit
         call state_at_param(model, params, ch, i, x, s, status, errmsg)
         if (status /= wa_ok) return
         call brent_accept(solver, s%gbar - g)
      end do
      x = solver%b
      if (x1 /= x0) then
         s_to = real(i - 1, wp) + (x - x0)/(x1 - x0)
      else
         s_to = real(i - 1, wp)
      end if
   end subroutine solve_gbar

   ! ---------------------------------------------------------------- panels

   !> Cover the walked stretches of the chain with pieces and panels (n_nodes per panel,
   !> every piece first split into n_splits panels).
   !> net_only: only the pieces walked a net number of times (what W* needs; the gap law
   !> needs every walked piece).
   subroutine build_cover(model, params, ch, walked, n_nodes, n_splits, cov, status, errmsg, &
         net_only)
      integer, intent(in) :: model, n_nodes, n_splits
      logical, intent(in), optional :: net_only
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      type(stretch_type), intent(in) :: walked(:)
      type(cover_type), intent(out) :: cov
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), allocatable :: cuts(:)
      real(wp) :: lo, hi, x_lo, x_hi, u_lo, u_hi, du, ua, ub, ic
      real(wp) :: pc(n_nodes), gc(n_nodes)
      integer :: k, j, n_cuts, kind, p, n_first, node
      logical :: found, near_zero
      real(wp) :: d

      status = wa_ok
      call make_rule(n_nodes, cov%rule)
      allocate (cuts(2*size(walked) + ch%n + 2))
      n_cuts = 0
      do k = 1, size(walked)
         call put(walked(k)%s1); call put(walked(k)%s2)
      end do
      call put(0.0_wp); call put(real(ch%n - 1, wp))
      do j = 2, ch%n - 1                               ! breaks of the parameter at node j
         if (param_kind(ch, j - 1) /= param_kind(ch, j) .or. ch%event(j) == event_switch .or. &
            ch%zone(j) /= ch%zone(j - 1) .or. ch%zone(j) /= ch%zone(j + 1) .or. &
            (param(ch, j - 1, 1.0_wp) - param(ch, j - 1, 0.0_wp))* &
            (param(ch, j, 1.0_wp) - param(ch, j, 0.0_wp)) <= 0.0_wp) call put(real(j - 1, wp))
      end do
      call sort(cuts(1:n_cuts))
      allocate (cov%s0(n_cuts), cov%s1(n_cuts), cov%integral(n_cuts), cov%i_lo(n_cuts), &
         cov%i_hi(n_cuts), cov%first(n_cuts), cov%last(n_cuts), cov%var(n_cuts), &
         cov%anchor(n_cuts), cov%side(n_cuts), cov%constant_load(n_cuts), cov%u_start(n_cuts), &
         cov%u_end(n_cuts))
      call grow(cov, n_nodes, 64)
      do j = 1, n_cuts - 1
         lo = cuts(j); hi = cuts(j + 1)
         if (hi <= lo) cycle
         if (.not. any([(min(walked(k)%s1, walked(k)%s2) <= lo .and. &
            max(walked(k)%s1, walked(k)%s2) >= hi, k=1, size(walked))])) cycle
         if (present(net_only)) then                ! W* only: skip what cancels
            if (net_only .and. sum([(merge(sign(1.0_wp, walked(k)%s2 - walked(k)%s1), &
               0.0_wp, min(walked(k)%s1, walked(k)%s2) <= lo .and. &
               max(walked(k)%s1, walked(k)%s2) >= hi), k=1, size(walked))]) == 0.0_wp) cycle
         end if
         cov%n_pieces = cov%n_pieces + 1
         p = cov%n_pieces
         cov%s0(p) = lo; cov%s1(p) = hi
         cov%i_lo(p) = min(int(lo), ch%n - 2) + 1
         cov%i_hi(p) = max(cov%i_lo(p), min(ceiling(hi), ch%n - 1))
         cov%first(p) = cov%n_panels + 1; cov%last(p) = cov%n_panels
         cov%var(p) = var_x; cov%constant_load(p) = .false.
         cov%integral(p) = 0.0_wp
         kind = param_kind(ch, cov%i_lo(p))
         if (kind == 2) then                          ! P* = -Sigma0: exact
            cov%constant_load(p) = .true.
            cov%integral(p) = -params%sigma0*(piece_gbar(cov, ch, p, hi) - &
               piece_gbar(cov, ch, p, lo))
            cycle
         end if
         x_lo = param(ch, cov%i_lo(p), lo - real(cov%i_lo(p) - 1, wp))
         x_hi = param(ch, cov%i_hi(p), hi - real(cov%i_hi(p) - 1, wp))
         cov%var(p) = var_x; cov%anchor(p) = 0.0_wp; cov%side(p) = 1.0_wp
         u_lo = x_lo; u_hi = x_hi
         near_zero = (kind == 0 .or. kind == 1) .and. min(x_lo, x_hi) > 0.0_wp .and. &
            min(x_lo, x_hi) < 1.0e-3_wp*abs(x_hi - x_lo)
         found = .false.
         if (kind == 0) call root_anchor(ch, cov%i_lo(p), cov%i_hi(p), x_lo, x_hi, &
            cov%anchor(p), found)
         if (found) then
            cov%side(p) = sign(1.0_wp, 0.5_wp*(x_lo + x_hi) - cov%anchor(p))
            d = min(abs(x_lo - cov%anchor(p)), abs(x_hi - cov%anchor(p)))
            if (d < 1.0e-3_wp*abs(x_hi - x_lo)) then     ! ends at the anchor
               cov%var(p) = var_root
               u_lo = sqrt(abs(x_lo - cov%anchor(p))); u_hi = sqrt(abs(x_hi - cov%anchor(p)))
            else if (near_zero .and. cov%side(p) < 0.0_wp) then
               cov%var(p) = var_logit
               u_lo = log(x_lo/(cov%anchor(p) - x_lo)); u_hi = log(x_hi/(cov%anchor(p) - x_hi))
            else
               cov%var(p) = var_log_distance
               u_lo = log(abs(x_lo - cov%anchor(p))); u_hi = log(abs(x_hi - cov%anchor(p)))
            end if
         else if (near_zero) then
            cov%var(p) = var_log
            u_lo = log(x_lo); u_hi = log(x_hi)
         end if
         cov%u_start(p) = u_lo; cov%u_end(p) = u_hi
         ! first panels: n_splits equal ones in u, or (default) one per chain_per_panel
         ! chain intervals, cut at chain nodes: the tracer's steps follow the curvature,
         ! so few of these panels are bisected again (each bisection wastes a panel)
         n_first = n_splits
         if (n_splits == 1) n_first = max(1, nint((hi - lo)/chain_per_panel))
         du = (u_hi - u_lo)/real(n_first, wp)
         ua = u_lo
         do k = 1, n_first
            if (k == n_first) then
               ub = u_hi
            else if (n_splits > 1) then
               ub = u_lo + du*real(k, wp)
            else
               node = nint(lo + (hi - lo)*real(k, wp)/real(n_first, wp))
               if (node <= lo .or. node >= hi) cycle
               ub = u_of(cov, p, param(ch, node + 1, 0.0_wp))
               if (.not. ((ub - ua)*(u_hi - u_lo) > 0.0_wp .and. (u_hi - ub)*(u_hi - u_lo) &
                  > 0.0_wp)) cycle                       ! not strictly inside: merge
            end if
            call eval_panel(model, params, ch, cov, p, ua, ub, pc, gc, ic, status, errmsg)
            if (status /= wa_ok) return
            call adapt(model, params, ch, cov, p, ua, ub, pc, gc, ic, 0, status, errmsg)
            if (status /= wa_ok) return
            ua = ub
         end do
         cov%last(p) = cov%n_panels
         cov%integral(p) = sum(cov%pint(cov%first(p):cov%last(p)))
      end do
   contains
      subroutine put(x)
         real(wp), intent(in) :: x
         if (x < 0.0_wp) return
         n_cuts = n_cuts + 1
         cuts(n_cuts) = x
      end subroutine put
   end subroutine build_cover

   !> Keep the panel [ua, ub] of piece p (values pc, gc, integral ic at its nodes) if its
   !> interpolants are resolved, else bisect it; store the kept panels in order.
   recursive subroutine adapt(model, params, ch, cov, p, ua, ub, pc, gc, ic, depth, status, &
         errmsg, parent_tails)
      integer, intent(in) :: model, p, depth
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      type(cover_type), intent(inout) :: cov
      real(wp), intent(in) :: ua, ub, pc(:), gc(:), ic
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      !> the Legendre tails of P* and gbar* on the parent panel
      real(wp), intent(in), optional :: parent_tails(2)
      real(wp) :: um, pl(size(pc)), gl(size(pc)), il, pr(size(pc)), gr(size(pc)), ir
      real(wp) :: frac, x1, xn, noise_p, noise_g, tails(2)
      status = wa_ok
      tails = [legendre_tail(cov%rule, pc), legendre_tail(cov%rule, gc)]
      ! evaluation noise (MD's quadratures: ~1e-13 of P* at large alpha): halving did not
      ! shrink the tails, which are already at the noise level of the values; a
      ! resolved panel's tails shrink ~2^16 on halving, a square-root end's ~2^0.5
      if (present(parent_tails)) then
         if (all(tails >= 0.25_wp*parent_tails) .and. &
            tails(1) <= noise_level*maxval(abs(pc)) .and. &
            tails(2) <= noise_level*maxval(abs(gc))) then
            call store(cov, ua, ub, pc, gc, ic)
            return
         end if
      end if
      ! tolerance per panel: relative to its own values, or to the chain's scale times
      ! its share of the piece (an end singularity then costs a few bisections), or to
      ! the rounding of P* and gbar* (~100 ulps of the chain's largest: cancellation)
      frac = max(tol_value*abs(ub - ua)/abs(cov%u_end(p) - cov%u_start(p)), &
         100.0_wp*epsilon(1.0_wp))
      ! (or the panel spans a few hundred ulps of x: the rounding of x itself then
      ! decides the values and bisecting cannot help; its share of W* is that small).
      ! The rounding of x moves a steep P* or gbar* by eps |x df/dx|: a floor too.
      x1 = x_of(cov, p, 0.5_wp*(ua + ub) + 0.5_wp*(ub - ua)*cov%rule%x(1))
      xn = x_of(cov, p, 0.5_wp*(ua + ub) + 0.5_wp*(ub - ua)*cov%rule%x(size(pc)))
      if (xn /= x1) then
         noise_p = 100.0_wp*epsilon(1.0_wp)*abs(x1)*abs(pc(size(pc)) - pc(1))/abs(xn - x1)
         noise_g = 100.0_wp*epsilon(1.0_wp)*abs(x1)*abs(gc(size(pc)) - gc(1))/abs(xn - x1)
      else
         noise_p = huge(1.0_wp); noise_g = huge(1.0_wp)
      end if
      if ((resolved(cov%rule, pc, max(frac*maxval(abs(ch%p(1:ch%n))), noise_p)) .and. &
         resolved(cov%rule, gc, max(frac*maxval(abs(ch%g(1:ch%n))), noise_g))) .or. &
         abs(x_of(cov, p, ub) - x_of(cov, p, ua)) <= &
         256.0_wp*epsilon(1.0_wp)*abs(x_of(cov, p, ua))) then
         call store(cov, ua, ub, pc, gc, ic)
         return
      end if
      um = 0.5_wp*(ua + ub)
      if (depth >= max_depth .or. um == ua .or. um == ub .or. cov%n_panels >= max_panels) then
         call set_error(wa_numerical_error, "gap_path: the quadrature along the branch "// &
            "does not converge", status, errmsg)
         return
      end if
      call eval_panel(model, params, ch, cov, p, ua, um, pl, gl, il, status, errmsg)
      if (status /= wa_ok) return
      call eval_panel(model, params, ch, cov, p, um, ub, pr, gr, ir, status, errmsg)
      if (status /= wa_ok) return
      call adapt(model, params, ch, cov, p, ua, um, pl, gl, il, depth + 1, status, errmsg, &
         tails)
      if (status /= wa_ok) return
      call adapt(model, params, ch, cov, p, um, ub, pr, gr, ir, depth + 1, status, errmsg, &
         tails)
   end subroutine adapt

   !> The Legendre series of the values f at the rule's nodes has decayed: its last
   !> three coefficients are below tol_value times the largest, or a few ulps of max |f|,
   !> or tol_abs.
   !> The largest of the last three Legendre coefficients of the values f at the nodes.
   pure real(wp) function legendre_tail(rule, f) result(tail)
      type(rule_type), intent(in) :: rule
      real(wp), intent(in) :: f(:)
      real(wp) :: c(rule%n)
      c = matmul(rule%leg, f)
      tail = maxval(abs(c(rule%n - 2:rule%n)))
   end function legendre_tail

   pure logical function resolved(rule, f, tol_abs)
      type(rule_type), intent(in) :: rule
      real(wp), intent(in) :: f(:), tol_abs
      real(wp) :: c(rule%n), tail
      c = matmul(rule%leg, f)
      tail = maxval(abs(c(rule%n - 2:rule%n)))
      resolved = tail <= max(tol_value*maxval(abs(c)) + 16.0_wp*epsilon(1.0_wp)*maxval(abs(f)), &
         tol_abs)
   end function resolved

   !> P* and gbar* at the nodes of [ua, ub] in the variable of piece p, and int P* dgbar*
   !> from ua to ub (dgbar*/du from the interpolating polynomial through the nodes).
   subroutine eval_panel(model, params, ch, cov, p, ua, ub, pv, gv, integral, status, errmsg)
      integer, intent(in) :: model, p
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      type(cover_type), intent(in) :: cov
      real(wp), intent(in) :: ua, ub
      real(wp), intent(out) :: pv(:), gv(:), integral
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: s
      type(y_hint_type) :: hint
      real(wp) :: u, x
      integer :: j, i
      status = wa_ok
      integral = 0.0_wp
      do j = 1, cov%rule%n
         u = 0.5_wp*(ua + ub) + 0.5_wp*(ub - ua)*cov%rule%x(j)
         x = x_of(cov, p, u)
         i = interval_of(ch, cov%i_lo(p), cov%i_hi(p), x)
         call state_at_param(model, params, ch, i, x, s, status, errmsg, hint)
         if (status /= wa_ok) return
         pv(j) = s%p_star; gv(j) = s%gbar
      end do
      integral = sum(cov%rule%w*pv*matmul(cov%rule%d, gv))
   end subroutine eval_panel

   !> The a* of the zone switch or a* turn that the case-1 stretch of pieces i_lo..i_hi
   !> runs into next to the piece (the chain followed outwards from both ends while it
   !> stays in case 1), when it lies beyond the piece's a* range [x_lo, x_hi] by less than
   !> that range's width (else found = .false.).
   pure subroutine root_anchor(ch, i_lo, i_hi, x_lo, x_hi, anchor, found)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i_lo, i_hi
      real(wp), intent(in) :: x_lo, x_hi
      real(wp), intent(out) :: anchor
      logical, intent(out) :: found
      real(wp) :: d, d_best, lo, hi
      integer :: j, dir, k
      found = .false.
      anchor = 0.0_wp
      if (ch%zone(i_lo) /= zone_inside .and. ch%zone(i_hi + 1) /= zone_inside) return
      lo = min(x_lo, x_hi); hi = max(x_lo, x_hi)
      d_best = hi - lo
      do dir = -1, 1, 2
         j = merge(i_lo, i_hi + 1, dir < 0)
         do k = 1, ch%n
            if (j < 1 .or. j > ch%n) exit
            if (ch%event(j) == event_switch .or. ch%event(j) == event_a_turn) then
               d = max(lo - ch%a(j), ch%a(j) - hi)
               if (d >= 0.0_wp .and. d < d_best) then
                  d_best = d; anchor = ch%a(j); found = .true.
               end if
               exit
            end if
            if (ch%zone(j) /= zone_inside) exit
            j = j + dir
         end do
      end do
   end subroutine root_anchor

   !> The chain parameter x at u in the variable of piece p.
   pure real(wp) function x_of(cov, p, u) result(x)
      type(cover_type), intent(in) :: cov
      integer, intent(in) :: p
      real(wp), intent(in) :: u
      select case (cov%var(p))
      case (var_log)
         x = exp(u)
      case (var_root)
         x = cov%anchor(p) + cov%side(p)*u*u
      case (var_log_distance)
         x = cov%anchor(p) + cov%side(p)*exp(u)
      case (var_logit)
         x = cov%anchor(p)/(1.0_wp + exp(-u))
      case default
         x = u
      end select
   end function x_of

   !> The variable u of piece p at parameter x (the inverse of x_of).
   pure real(wp) function u_of(cov, p, x) result(u)
      type(cover_type), intent(in) :: cov
      integer, intent(in) :: p
      real(wp), intent(in) :: x
      select case (cov%var(p))
      case (var_log)
         u = log(x)
      case (var_root)
         u = sqrt(abs(x - cov%anchor(p)))
      case (var_log_distance)
         u = log(abs(x - cov%anchor(p)))
      case (var_logit)
         u = log(x/(cov%anchor(p) - x))
      case default
         u = x
      end select
   end function u_of

   !> The chain interval among i_lo..i_hi whose parameter range holds x (the nearest
   !> end interval when x is outside by rounding).
   pure integer function interval_of(ch, i_lo, i_hi, x) result(i)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i_lo, i_hi
      real(wp), intent(in) :: x
      real(wp) :: x0, x1, d
      integer :: lo, hi, mid
      ! the parameter is monotone over a piece's intervals: the first interval whose far
      ! end is not before x, by bisection
      d = sign(1.0_wp, param(ch, i_hi, 1.0_wp) - param(ch, i_lo, 0.0_wp))
      lo = i_lo; hi = i_hi
      do while (lo < hi)
         mid = (lo + hi)/2
         if (d*(param(ch, mid, 1.0_wp) - x) >= 0.0_wp) then
            hi = mid
         else
            lo = mid + 1
         end if
      end do
      i = lo
      x0 = param(ch, i, 0.0_wp); x1 = param(ch, i, 1.0_wp)
      if ((x - x0)*(x - x1) <= 0.0_wp) return
      x0 = param(ch, i_lo, 0.0_wp)
      x1 = param(ch, i_hi, 1.0_wp)
      i = merge(i_lo, i_hi, abs(x - x0) <= abs(x - x1))
   end function interval_of

   subroutine store(cov, ua, ub, pv, gv, integral)
      type(cover_type), intent(inout) :: cov
      real(wp), intent(in) :: ua, ub, pv(:), gv(:), integral
      integer :: j
      if (cov%n_panels >= size(cov%u0)) call grow(cov, cov%rule%n, 2*size(cov%u0))
      cov%n_panels = cov%n_panels + 1
      j = cov%n_panels
      cov%u0(j) = ua; cov%u1(j) = ub
      cov%pv(:, j) = pv; cov%gv(:, j) = gv; cov%pint(j) = integral
      cov%g0(j) = interpolate(cov%rule, gv, -1.0_wp)
      cov%g1(j) = interpolate(cov%rule, gv, 1.0_wp)
   end subroutine store

   subroutine grow(cov, n_nodes, capacity)
      type(cover_type), intent(inout) :: cov
      integer, intent(in) :: n_nodes, capacity
      real(wp), allocatable :: t1(:), t2(:, :)
      integer :: m
      m = cov%n_panels
      if (.not. allocated(cov%u0)) then
         allocate (cov%u0(capacity), cov%u1(capacity), cov%g0(capacity), cov%g1(capacity), &
            cov%pint(capacity), cov%pv(n_nodes, capacity), cov%gv(n_nodes, capacity))
         return
      end if
      allocate (t1(capacity)); t1(1:m) = cov%u0(1:m); call move_alloc(t1, cov%u0)
      allocate (t1(capacity)); t1(1:m) = cov%u1(1:m); call move_alloc(t1, cov%u1)
      allocate (t1(capacity)); t1(1:m) = cov%g0(1:m); call move_alloc(t1, cov%g0)
      allocate (t1(capacity)); t1(1:m) = cov%g1(1:m); call move_alloc(t1, cov%g1)
      allocate (t1(capacity)); t1(1:m) = cov%pint(1:m); call move_alloc(t1, cov%pint)
      allocate (t2(n_nodes, capacity)); t2(:, 1:m) = cov%pv(:, 1:m); call move_alloc(t2, cov%pv)
      allocate (t2(n_nodes, capacity)); t2(:, 1:m) = cov%gv(:, 1:m); call move_alloc(t2, cov%gv)
   end subroutine grow

   !> gbar* at position s (within its span) of constant-load piece p (linear in s there).
   pure real(wp) function piece_gbar(cov, ch, p, s_pos) result(g)
      type(cover_type), intent(in) :: cov
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: p
      real(wp), intent(in) :: s_pos
      integer :: i
      real(wp) :: t
      i = max(cov%i_lo(p), min(int(s_pos) + 1, cov%i_hi(p)))
      t = s_pos - real(i - 1, wp)
      g = ch%g(i) + t*(ch%g(i + 1) - ch%g(i))
   end function piece_gbar

   ! ---------------------------------------------------------------- energy

   !> path%w_star and path%w_fraction from the cover of the walked stretches; a negative
   !> W* beyond rounding (the terms are O(1)) means the walk or the quadrature failed.
   pure subroutine cycle_energy(params, cov, walked, path, status, errmsg)
      type(params_type), intent(in) :: params
      type(cover_type), intent(in) :: cov
      type(stretch_type), intent(in) :: walked(:)
      type(gap_path_type), intent(inout) :: path
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      status = wa_ok
      path%w_star = energy_lost(cov, walked)
      if (path%w_star < -1.0e-14_wp) then
         call set_error(wa_numerical_error, "gap control: negative energy lost per cycle "// &
            "(the walk or the quadrature failed)", status, errmsg)
         return
      end if
      path%w_star = max(path%w_star, 0.0_wp)
      path%w_fraction = path%w_star/(pi*params%alpha**2/2.0_wp)
   end subroutine cycle_energy

   !> W* = -sum over walked stretches of int P* dgbar*: the net number of traversals
   !> of each piece of the cover times its integral (stretches walked both ways cancel
   !> exactly).
   pure real(wp) function energy_lost(cov, walked) result(w)
      type(cover_type), intent(in) :: cov
      type(stretch_type), intent(in) :: walked(:)
      real(wp) :: m
      integer :: p, k
      w = 0.0_wp
      do p = 1, cov%n_pieces
         m = 0.0_wp
         do k = 1, size(walked)
            if (min(walked(k)%s1, walked(k)%s2) <= cov%s0(p) .and. &
               max(walked(k)%s1, walked(k)%s2) >= cov%s1(p)) &
               m = m + sign(1.0_wp, walked(k)%s2 - walked(k)%s1)
         end do
         w = w - m*cov%integral(p)
      end do
   end function energy_lost

   !> P* and dP*/dgbar* at gbar* = g on the walked stretches (the first that holds g);
   !> found = .false. where none does.
   pure subroutine law_on(cov, params, ch, stretches, g, p_out, dpdg, found)
      type(cover_type), intent(in) :: cov
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      type(stretch_type), intent(in) :: stretches(:)
      real(wp), intent(in) :: g
      real(wp), intent(out) :: p_out, dpdg
      logical, intent(out) :: found
      integer :: m, p, j, best
      real(wp) :: lo, hi, d, d_best, z
      p_out = 0.0_wp; dpdg = 0.0_wp; found = .false.
      do m = 1, size(stretches)
         lo = min(stretches(m)%s1, stretches(m)%s2)
         hi = max(stretches(m)%s1, stretches(m)%s2)
         if (hi <= lo) cycle
         best = 0; d_best = huge(1.0_wp)
         do p = 1, cov%n_pieces
            if (cov%s0(p) < lo .or. cov%s1(p) > hi) cycle
            if (cov%constant_load(p)) then
               d = outside(g, piece_gbar(cov, ch, p, cov%s0(p)), piece_gbar(cov, ch, p, cov%s1(p)))
               if (d < d_best) then
                  d_best = d; best = -p
               end if
               cycle
            end if
            do j = cov%first(p), cov%last(p)
               d = outside(g, cov%g0(j), cov%g1(j))
               if (d < d_best) then
                  d_best = d; best = j
               end if
            end do
         end do
         if (best == 0 .or. d_best > 1.0e-12_wp*(1.0_wp + abs(g))) cycle
         found = .true.
         if (best < 0) then
            p_out = -params%sigma0
            return
         end if
         z = invert(cov%rule, cov%gv(:, best), g)
         call value_slope(cov%rule, cov%pv(:, best), cov%gv(:, best), z, p_out, dpdg)
         return
      end do
   contains
      pure real(wp) function outside(x, a, b)
         real(wp), intent(in) :: x, a, b
         outside = max(0.0_wp, min(a, b) - x, x - max(a, b))
      end function outside
   end subroutine law_on

   ! --------------------------------------------------- polynomial interpolants

   !> Gauss-Legendre rule with n nodes, its barycentric weights and differentiation matrix.
   pure subroutine make_rule(n, rule)
      integer, intent(in) :: n
      type(rule_type), intent(out) :: rule
      integer :: j, l
      real(wp) :: p0(n), p1(n), p2(n)
      rule%n = n
      allocate (rule%x(n), rule%w(n), rule%bw(n), rule%d(n, n), rule%leg(n, n))
      call gauss_legendre(rule%x, rule%w)
      p0 = 1.0_wp; p1 = rule%x                    ! P_k(x_j) by the three-term recurrence
      rule%leg(1, :) = 0.5_wp*rule%w
      if (n > 1) rule%leg(2, :) = 1.5_wp*rule%w*p1
      do l = 2, n - 1
         p2 = (real(2*l - 1, wp)*rule%x*p1 - real(l - 1, wp)*p0)/real(l, wp)
         rule%leg(l + 1, :) = 0.5_wp*real(2*l + 1, wp)*rule%w*p2
         p0 = p1; p1 = p2
      end do
      do j = 1, n
         rule%bw(j) = 1.0_wp
         do l = 1, n
            if (l /= j) rule%bw(j) = rule%bw(j)/(rule%x(j) - rule%x(l))
         end do
      end do
      rule%d = 0.0_wp
      do j = 1, n
         do l = 1, n
            if (l == j) cycle
            rule%d(j, l) = (rule%bw(l)/rule%bw(j))/(rule%x(j) - rule%x(l))
            rule%d(j, j) = rule%d(j, j) - rule%d(j, l)
         end do
      end do
   end subroutine make_rule

   !> The interpolating polynomial through (rule%x, f) at z in [-1, 1] (barycentric).
   pure real(wp) function interpolate(rule, f, z) result(v)
      type(rule_type), intent(in) :: rule
      real(wp), intent(in) :: f(:), z
      real(wp) :: num, den, t
      integer :: j
      num = 0.0_wp; den = 0.0_wp
      do j = 1, rule%n
         if (z == rule%x(j)) then
            v = f(j)
            return
         end if
         t = rule%bw(j)/(z - rule%x(j))
         num = num + t*f(j); den = den + t
      end do
      v = num/den
   end function interpolate

   !> The interpolant of p and dp/dg = (dp/dz)/(dg/dz) at z.
   pure subroutine value_slope(rule, p, g, z, v, dpdg)
      type(rule_type), intent(in) :: rule
      real(wp), intent(in) :: p(:), g(:), z
      real(wp), intent(out) :: v, dpdg
      real(wp) :: zz, dp, dg, gz, t, den
      integer :: j
      zz = z
      if (any(zz == rule%x)) zz = zz + 8.0_wp*epsilon(zz)*merge(-1.0_wp, 1.0_wp, zz > 0.0_wp)
      v = interpolate(rule, p, zz)
      gz = interpolate(rule, g, zz)
      dp = 0.0_wp; dg = 0.0_wp; den = 0.0_wp
      do j = 1, rule%n                               ! Schneider-Werner derivative
         t = rule%bw(j)/(zz - rule%x(j))
         den = den + t
         dp = dp + t*(v - p(j))/(zz - rule%x(j))
         dg = dg + t*(gz - g(j))/(zz - rule%x(j))
      end do
      dpdg = 0.0_wp
      if (dg /= 0.0_wp) dpdg = dp/dg
   end subroutine value_slope

   !> z in [-1, 1] where the (monotone) interpolant of g equals target: bisection
   !> safeguarded Newton-secant (regula falsi with the Illinois rule).
   pure real(wp) function invert(rule, g, target) result(z)
      type(rule_type), intent(in) :: rule
      real(wp), intent(in) :: g(:), target
      real(wp) :: za, zb, fa, fb, fz
      integer :: it, side
      za = -1.0_wp; zb = 1.0_wp
      fa = interpolate(rule, g, za) - target
      fb = interpolate(rule, g, zb) - target
      if (fa == 0.0_wp) then
         z = za; return
      else if (fb == 0.0_wp .or. fa*fb > 0.0_wp) then
         z = merge(za, zb, abs(fa) < abs(fb)); return
      end if
      side = 0
      z = za
      do it = 1, 200
         z = (za*fb - zb*fa)/(fb - fa)
         if (.not. (z > za .and. z < zb)) z = 0.5_wp*(za + zb)
         fz = interpolate(rule, g, z) - target
         if (fz == 0.0_wp .or. zb - za <= 4.0_wp*epsilon(1.0_wp)) exit
         if (fz*fb > 0.0_wp) then
            zb = z; fb = fz
            if (side == 1) fa = 0.5_wp*fa
            side = 1
         else
            za = z; fa = fz
            if (side == -1) fb = 0.5_wp*fb
            side = -1
         end if
         if (abs(zb - za) <= 2.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(z))) exit
      end do
   end function invert

   pure subroutine sort(x)
      real(wp), intent(inout) :: x(:)
      integer :: i, j
      real(wp) :: t
      do i = 2, size(x)
         t = x(i)
         j = i - 1
         do while (j >= 1)
            if (x(j) <= t) exit
            x(j + 1) = x(j)
            j = j - 1
         end do
         x(j + 1) = t
      end do
   end subroutine sort

   !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
   pure subroutine gauss_legendre(x, w)
      real(wp), intent(out) :: x(:), w(:)
      integer :: n, i, k, it
      real(wp) :: z, p0, p1, p2, dp
      n = size(x)
      do i = 1, n
         z = cos(pi*(real(i, wp) - 0.25_wp)/(real(n, wp) + 0.5_wp))
         do it = 1, 100
            p0 = 1.0_wp; p1 = z
            do k = 2, n
               p2 = (real(2*k - 1, wp)*z*p1 - real(k - 1, wp)*p0)/real(k, wp)
               p0 = p1; p1 = p2
            end do
            dp = real(n, wp)*(z*p1 - p0)/(z*z - 1.0_wp)
            if (abs(p1/dp) < 1.0e-16_wp) exit
            z = z - p1/dp
         end do
         x(i) = z
         w(i) = 2.0_wp/((1.0_wp - z*z)*dp*dp)
      end do
   end subroutine gauss_legendre

   ! ------------------------------------------------------- point solves

   !> 1: chain interval i is parametrised by c* (no-contact states), else 0 (a*).
   pure integer function param_kind(ch, i)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i
      param_kind = 0
      if (ch%zone(i) == zone_no_contact .and. ch%zone(i + 1) == zone_no_contact) then
         param_kind = 1
         if (ch%c(i) == 0.5_wp .and. ch%c(i + 1) == 0.5_wp) param_kind = 2
      else if (ch%zone(i) == zone_inside .and. ch%zone(i + 1) == zone_inside .and. &
         (ch%model == model_dw .or. ch%model == model_md) .and. ch%event(i) /= event_switch &
         .and. ch%event(i + 1) /= event_switch) then
         ! steep in the (a*, w y) plane: y is the parameter (a* turns back there)
         if (abs(ch%a(i + 1) - ch%a(i)) < curve_weight(ch%model)*abs(ch%y(i + 1) - ch%y(i))) &
            param_kind = 3
      end if
   end function param_kind

   pure real(wp) function param(ch, i, t)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i
      real(wp), intent(in) :: t
      if (param_kind(ch, i) == 1) then
         param = ch%c(i) + t*(ch%c(i + 1) - ch%c(i))
      else if (param_kind(ch, i) == 2) then
         param = ch%g(i) + t*(ch%g(i + 1) - ch%g(i))
      else if (param_kind(ch, i) == 3) then
         param = ch%y(i) + t*(ch%y(i + 1) - ch%y(i))
      else
         param = ch%a(i) + t*(ch%a(i + 1) - ch%a(i))
      end if
   end function param

   pure function chain_state(ch, i) result(s)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i
      type(state_type) :: s
      s%a_star = ch%a(i); s%c_star = ch%c(i); s%p_star = ch%p(i); s%gbar = ch%g(i)
      s%zone_case = ch%zone(i)
      s%gap_width = ch%c(i) - ch%a(i)                 ! c* - a* (wa_state)
   end function chain_state

   !> The state of chain interval i at parameter x (with its gbar*).
   subroutine state_at_param(model, params, ch, i, x, s, status, errmsg, hint)
      integer, intent(in) :: model, i
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: x
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      !> the previous solutions of a run of nodes (updated)
      type(y_hint_type), intent(inout), optional :: hint
      real(wp) :: t, c_guess
      integer :: zone
      logical :: done
      if (param_kind(ch, i) /= 0 .and. present(hint)) hint%n = 0
      if (param_kind(ch, i) == 1) then
         call md_no_contact_state(params, min(x, 0.5_wp - epsilon(x)), s, status, errmsg)
         return
      else if (param_kind(ch, i) == 2) then           ! zone over the period: gbar = 1 + crest gap
         call md_no_contact_state(params, 0.5_wp, s, status, errmsg, &
            crest_gap=min(max(x - 1.0_wp, 0.0_wp), 2.0_wp*params%dcod - 2.0_wp))
         return
      else if (param_kind(ch, i) == 3) then
         call solve_at_y(model, params, ch, i, x, s, status, errmsg)
         return
      end if
      t = 0.5_wp
      if (ch%a(i + 1) /= ch%a(i)) t = (x - ch%a(i))/(ch%a(i + 1) - ch%a(i))
      call local_state(model, params, ch, i, x, t, s, done, status, errmsg, hint)
      if (done .or. status /= wa_ok) return
      c_guess = ch%c(i) + t*(ch%c(i + 1) - ch%c(i))
      zone = ch%zone(i + 1)
      if (ch%event(i + 1) == event_switch .or. zone == zone_full_contact) zone = ch%zone(i)
      if (zone == zone_no_contact .or. zone == zone_full_contact) zone = -1
      if (ch%event(i) == event_switch .and. ch%zone(i + 1) /= zone_full_contact) &
         zone = ch%zone(i + 1)
      call solve_at_a(model, params, x, c_guess, zone, s, status, errmsg)
      ! an interval that changes zone case without a switch point between (a fold at
      ! the switch): the equilibrium nearest the guess in any case
      if (status /= wa_ok .and. zone >= 0 .and. ch%zone(i) /= ch%zone(i + 1)) &
         call solve_at_a(model, params, x, c_guess, -1, s, status, errmsg)
   end subroutine state_at_param

   !> The state at a* = x on chain interval i (t: its position in the interval) without
   !> a root scan, where the interval allows: case 2 in closed form (c* = 1/2), case 1 of
   !> DW and MD by Brent on F(x, y) in y within the interval's y range (widened at most
   !> three times). done = .false.: not applicable here (the caller scans for roots).
   subroutine local_state(model, params, ch, i, x, t, s, done, status, errmsg, hint)
      use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
      integer, intent(in) :: model, i
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: x, t
      type(state_type), intent(out) :: s
      logical, intent(out) :: done
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(y_hint_type), intent(inout), optional :: hint
      type(brent_type) :: solver
      real(wp) :: y_guess, width, lo, hi, f_lo, f_hi, y, y_lin, step, slope
      logical :: conv, hinted, found
      integer :: iter, zi, zj
      done = .false.
      status = wa_ok
      hinted = .false.
      if (present(hint)) hinted = hint%n >= 2
      if (.not. (model == model_dw .or. model == model_md) .or. params%sigma0 <= 0.0_wp) return
      zi = ch%zone(i); zj = ch%zone(i + 1)
      if ((zi == zone_whole_period .or. zi == zone_full_contact) .and. &
         (zj == zone_whole_period .or. zj == zone_full_contact) .and. &
         .not. (zi == zone_full_contact .and. zj == zone_full_contact)) then
         s%a_star = x; s%c_star = 0.5_wp; s%gap_width = 0.5_wp - x
         s%p_star = curve_case2_load(model, params, x)
         s%zone_case = zone_whole_period
      else if (zi == zone_inside .and. zj == zone_inside .and. ch%event(i) /= event_switch &
         .and. ch%event(i + 1) /= event_switch .and. ch%y(i) < 0.0_wp .and. ch%y(i + 1) < 0.0_wp) then
         ! the guess: extrapolated from the previous nodes of the run (quadratic), the
         ! bracket stepped from it towards the root (the slope's sign is the previous
         ! node's); else interpolated along the chain interval, the bracket around it
         found = .false.
         if (hinted) then
            associate (hx => hint%x, hy => hint%y, m => hint%n)
               y_lin = hy(m) + (x - hx(m))*(hy(m) - hy(m - 1))/(hx(m) - hx(m - 1))
               y_guess = y_lin
               width = 0.25_wp*abs(y_lin - hy(m))
               if (m >= 3) then
                  y_guess = hy(1)*(x - hx(2))*(x - hx(3))/((hx(1) - hx(2))*(hx(1) - hx(3))) &
                     + hy(2)*(x - hx(1))*(x - hx(3))/((hx(2) - hx(1))*(hx(2) - hx(3))) &
                     + hy(3)*(x - hx(1))*(x - hx(2))/((hx(3) - hx(1))*(hx(3) - hx(2)))
                  width = 0.25_wp*abs(y_guess - y_lin)
               end if
            end associate
            y_guess = min(y_guess, 0.0_wp)
            width = max(width, 1.0e-13_wp*abs(y_guess))
            f_lo = curve_residual(model, params, x, y_guess)
            step = -sign(width, f_lo*hint%slope)
            lo = y_guess
            do iter = 1, 12
               hi = min(lo + step, 0.0_wp)
               f_hi = curve_residual(model, params, x, hi)
               if (f_lo*f_hi <= 0.0_wp) then
                  found = .true.
                  exit
               end if
               lo = hi; f_lo = f_hi
               step = 4.0_wp*step
            end do
         end if
         if (.not. found) then
            y_guess = ch%y(i) + t*(ch%y(i + 1) - ch%y(i))
            width = 0.125_wp*abs(ch%y(i + 1) - ch%y(i)) + 1.0e-9_wp*abs(y_guess)
            do iter = 1, 4
               lo = y_guess - width; hi = min(y_guess + width, 0.0_wp)
               f_lo = curve_residual(model, params, x, lo)
               f_hi = curve_residual(model, params, x, hi)
               ! F falls through the root where the branch runs backwards in a*
               if (f_lo*f_hi <= 0.0_wp) exit
               width = 4.0_wp*width
            end do
         end if
         if (.not. (f_lo*f_hi <= 0.0_wp)) then
            if (present(hint)) hint%n = 0
            return
         end if
         slope = sign(1.0_wp, (f_hi - f_lo)*(hi - lo))
         ! tolerance: the rounding noise of F moves its root by ~10 ulps of y; a tighter
         ! one only spends evaluations closing the bracket against that noise
         call brent_init(solver, lo, f_lo, hi, f_hi, 32.0_wp*epsilon(1.0_wp)*abs(y_guess))
         do iter = 1, 200
            call brent_propose(solver, y, conv, settle=.true.)
            if (conv) exit
            call brent_accept(solver, curve_residual(model, params, x, y))
         end do
         if (.not. conv) return
         s = curve_state(model, params, x, solver%b)
         ! (finite without ieee_is_finite, and no local use of a module that uses
         ! ieee_arithmetic: either makes gfortran save and restore the floating-point
         ! state around every point solve)
         if (s%zone_case /= zone_inside .or. .not. abs(s%p_star) <= huge(1.0_wp)) then
            if (present(hint)) hint%n = 0
            return
         end if
         if (present(hint)) then
            if (hint%n == 3) then
               hint%x(1:2) = hint%x(2:3); hint%y(1:2) = hint%y(2:3)
            end if
            hint%n = min(hint%n + 1, 3)
            hint%x(hint%n) = x; hint%y(hint%n) = solver%b
            hint%slope = slope
         end if
      else
         if (present(hint)) hint%n = 0
         return
      end if
      ! a solved state of the branch: its mean gap needs no argument checks
      if (model == model_dw) then
         s%gbar = dw_state_gbar(params, s)
      else
         s%gbar = md_state_gbar(params, s)
      end if
      done = abs(s%gbar) <= huge(1.0_wp)
   end subroutine local_state

   !> The case-1 state of chain interval i at curve variable y: Brent on F(a*, y) in a*
   !> over the interval's a* range, widened until F changes sign.
   subroutine solve_at_y(model, params, ch, i, y, s, status, errmsg)
      use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
      integer, intent(in) :: model, i
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: y
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: lo, hi, f_lo, f_hi, width, a
      logical :: done
      integer :: iter
      width = abs(ch%a(i + 1) - ch%a(i)) + 1.0e-14_wp
      lo = min(ch%a(i), ch%a(i + 1)); hi = max(ch%a(i), ch%a(i + 1))
      do iter = 1, 60
         lo = max(lo - width, 0.5_wp*lo)
         hi = min(hi + width, 0.5_wp*(hi + 0.5_wp))
         f_lo = curve_residual(model, params, lo, y)
         f_hi = curve_residual(model, params, hi, y)
         if (f_lo*f_hi <= 0.0_wp) exit
         width = 2.0_wp*width
      end do
      if (.not. (f_lo*f_hi <= 0.0_wp)) then
         call set_error(wa_numerical_error, "gap_path: no case-1 state at this curve "// &
            "variable near the branch", status, errmsg)
         return
      end if
      call brent_init(solver, lo, f_lo, hi, f_hi, 1.0e-16_wp)
      do iter = 1, 200
         call brent_propose(solver, a, done, settle=.true.)
         if (done) exit
         call brent_accept(solver, curve_residual(model, params, a, y))
      end do
      s = curve_state(model, params, solver%b, y)
      call state_mean_gap(model, params, s, s%gbar, status, errmsg)
   end subroutine solve_at_y

   !> The equilibrium at a* nearest c_guess (in zone case `zone` unless zone < 0).
   subroutine solve_at_a(model, params, a, c_guess, zone, s, status, errmsg)
      integer, intent(in) :: model, zone
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, c_guess
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(state_type) :: roots(max_model_roots)
      integer :: n, k, best
      real(wp) :: d, d_best
      call model_roots(model, params, a, roots, n, status, errmsg)
      if (status /= wa_ok) return
      best = 0
      d_best = huge(1.0_wp)
      do k = 1, min(n, size(roots))
         if (zone >= 0 .and. roots(k)%zone_case /= zone) cycle
         d = abs(roots(k)%c_star - c_guess)
         if (d < d_best) then
            d_best = d; best = k
         end if
      end do
      if (best == 0) then
         call set_error(wa_numerical_error, "gap_path: no equilibrium near the branch at "// &
            "a point of the quadrature", status, errmsg)
         return
      end if
      s = roots(best)
      call state_mean_gap(model, params, s, s%gbar, status, errmsg)
   end subroutine solve_at_a

   ! ----------------------------------------------------------- event list

   subroutine add(path, stage, event, s)
      type(gap_path_type), intent(inout) :: path
      integer, intent(in) :: stage, event
      type(state_type), intent(in) :: s
      if (path%n >= max_events) return
      path%n = path%n + 1
      path%stage(path%n) = stage; path%event(path%n) = event
      path%a_star(path%n) = s%a_star; path%c_star(path%n) = s%c_star
      path%p_star(path%n) = s%p_star; path%gbar(path%n) = s%gbar
      path%zone_case(path%n) = s%zone_case
   end subroutine add

   !> An event on the P* = 0 states (surfaces apart) at gbar* = g.
   subroutine add_far(path, stage, event, g)
      type(gap_path_type), intent(inout) :: path
      integer, intent(in) :: stage, event
      real(wp), intent(in) :: g
      type(state_type) :: s
      s%gbar = g
      s%zone_case = zone_no_contact
      call add(path, stage, event, s)
   end subroutine add_far

   !> The event at chain position s_pos. g_jump: the gbar* of the jump that lands there
   !> (the landing keeps it: its solve in solve_gbar leaves gbar* within the parameter's
   !> tolerance of it, relative 1e-11 and worse near full contact, so the event gets the
   !> jump's gbar* exactly, the contract of a jump under gap control).
   subroutine add_at(model, params, ch, path, stage, event, s_pos, status, errmsg, g_jump)
      integer, intent(in) :: model, stage, event
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      type(gap_path_type), intent(inout) :: path
      real(wp), intent(in) :: s_pos
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), intent(in), optional :: g_jump
      type(state_type) :: s
      integer :: i
      real(wp) :: t
      status = wa_ok
      i = min(int(s_pos), ch%n - 2) + 1
      t = s_pos - real(i - 1, wp)
      if (t == 0.0_wp) then
         s = chain_state(ch, i)
      else if (t == 1.0_wp) then
         s = chain_state(ch, i + 1)
      else
         call state_at_param(model, params, ch, i, param(ch, i, t), s, status, errmsg)
         if (status /= wa_ok) return
      end if
      if (present(g_jump)) s%gbar = g_jump
      call add(path, stage, event, s)
   end subroutine add_at

   ! ------------------------------------------------ critical values (appended)

   !> The events of the gap-controlled cycle (as gap_path, without W*: path%w_star = 0),
   !> the most tensile load on the retraction, p_min, with its gbar* and a*, and
   !> g_contact, the gbar* where contact (a* > 0, or MD's contact-made event) is first
   !> made on the approach.
   !> Invariant: p_min is the minimum of P* over every state the retraction passes, the
   !> end points of its jumps included. Along a walked stretch P* is extremal only at a
   !> fold of P* (a point of the traced branch, located to ~1e-11 in a*) or at a corner
   !> (a point too), so the minimum is taken over the retraction's events, the chain
   !> points its stretches cover, and the traced points that the refinement of a gbar*
   !> extremum replaced where its stretches cover their positions (at small alpha a fold
   !> of P* lies within one node of the gbar* maximum the retraction jumps from: it used
   !> to be lost, and P_min was the jump's start, up to 2 % less tensile).
   subroutine gap_cycle_critical(model, params, branch, path, p_min, g_min, a_min, g_contact, &
         status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(gap_path_type), intent(out) :: path
      real(wp), intent(out) :: p_min, g_min, a_min, g_contact
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(chain_type) :: ch
      type(stretch_type) :: walked(2*max_jumps + 4)
      type(state_type) :: s
      integer :: n_walked, n_approach, k, i
      real(wp) :: lo, hi, g_end

      p_min = huge(1.0_wp); g_min = 0.0_wp; a_min = 0.0_wp; g_contact = -1.0_wp
      call walk_cycle(model, params, branch, ch, path, walked, n_walked, n_approach, &
         status, errmsg)
      if (status /= wa_ok) return
      if (.not. ch%joined) g_contact = path%g_touch  ! the chain is all contact states
      do k = 1, path%n
         if (path%stage(k) == gap_stage_approach .and. g_contact < 0.0_wp .and. &
            (path%event(k) == gap_event_contact_made .or. path%a_star(k) > 0.0_wp)) &
            g_contact = path%gbar(k)
         if (path%stage(k) /= gap_stage_retraction) cycle
         if (path%p_star(k) < p_min) then
            p_min = path%p_star(k); g_min = path%gbar(k); a_min = path%a_star(k)
         end if
      end do
      do k = n_approach + 1, n_walked
         lo = min(walked(k)%s1, walked(k)%s2)
         hi = max(walked(k)%s1, walked(k)%s2)
         do i = max(1, ceiling(lo) + 1), min(ch%n, floor(hi) + 1)
            if (ch%p(i) < p_min) then
               p_min = ch%p(i); g_min = ch%g(i); a_min = ch%a(i)
            end if
         end do
         ! the stretch ends at a chain point, its largest gbar*: a state beyond it is not
         ! passed (where round-off hides a turn of gbar*, alpha below ~1e-10)
         g_end = ch%g(nint(walked(k)%s2) + 1)
         do i = 1, ch%n_moved                        ! traced points a refinement replaced
            if (ch%moved_s(i) >= lo .and. ch%moved_s(i) <= hi .and. ch%moved_p(i) < p_min &
               .and. ch%moved_g(i) <= g_end) then
               p_min = ch%moved_p(i); g_min = ch%moved_g(i); a_min = ch%moved_a(i)
            end if
         end do
         do i = max(1, int(lo) + 1), min(ch%n - 1, ceiling(hi))   ! intervals below a_start
            if (.not. below_tracer(ch, i) .or. hi <= real(i - 1, wp) .or. lo >= real(i, wp)) &
               cycle
            call floor_minimum(model, params, ch, i, max(lo - real(i - 1, wp), 0.0_wp), &
               min(hi - real(i - 1, wp), 1.0_wp), s, status, errmsg)
            if (status /= wa_ok) return
            if (s%p_star < p_min .and. s%gbar <= g_end) then
               p_min = s%p_star; g_min = s%gbar; a_min = s%a_star
            end if
         end do
      end do
      if (.not. (p_min < huge(1.0_wp) .and. g_contact >= 0.0_wp)) call set_error( &
         wa_numerical_error, "gap_path: the cycle has no retraction or makes no contact", &
         status, errmsg)
   end subroutine gap_cycle_critical

   !> Does chain interval i reach below the tracer's first point a* = a_start (1e-6)?
   !> The a_limit extension of a contact curve, or the joint between the closure of MD's
   !> no-contact states (a* = 0) and the contact curve (or a part of either between
   !> samples of sample_floor_intervals): no traced point inside, case 1 in a* (or in
   !> the curve variable y).
   pure logical function below_tracer(ch, i)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i
      below_tracer = ch%untraced(i) .and. (param_kind(ch, i) == 0 .or. param_kind(ch, i) == 3)
   end function below_tracer

   !> The state of least P* on chain interval i between t0 and t1 (a below_tracer
   !> interval). There P* - P*(a* -> 0) ~ a*^2 (k1 ln a* + k2) (doc/theory.md), which can
   !> have a minimum, a fold of P* that no traced point shows (DW, alpha = 1e-7, mu = 0.91:
   !> at a* ~ 3.5e-7, 1.2e-3 more tensile than P*(a* -> 0)). That form is unimodal in
   !> ln a*: golden sections in ln a* over a* >= 1e-9 of the upper end (a minimum further
   !> down is below 1e-18 of P*'s variation over the interval), to 1e-6 in ln a*
   !> (P* to ~1e-12 of that variation), or in the curve variable y where that is the
   !> interval's parameter (a* steep in it), to 1e-9 of its range. Where the sections
   !> close on an end of the range, P* is monotone there: s is the better end point of
   !> the interval (a chain point, as solved by the tracer).
   subroutine floor_minimum(model, params, ch, i, t0, t1, s, status, errmsg)
      integer, intent(in) :: model, i
      type(params_type), intent(in) :: params
      type(chain_type), intent(in) :: ch
      real(wp), intent(in) :: t0, t1
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp), parameter :: c = 0.3819660112501051518_wp
      type(state_type) :: s1, s2
      real(wp) :: ua, ub, x1, x2, a_lo, a_hi, tol, u_first, u_last
      integer :: it
      logical :: in_log

      status = wa_ok
      in_log = param_kind(ch, i) == 0
      a_lo = min(param(ch, i, t0), param(ch, i, t1))
      a_hi = max(param(ch, i, t0), param(ch, i, t1))
      s = chain_state(ch, i)
      if (ch%p(i + 1) < s%p_star) s = chain_state(ch, i + 1)
      if (in_log) then
         if (.not. (a_hi > 0.0_wp)) return
         ua = log(max(a_lo, 1.0e-9_wp*a_hi)); ub = log(a_hi)
         tol = 1.0e-6_wp
      else
         ua = a_lo; ub = a_hi
         tol = 1.0e-9_wp*(ub - ua)
      end if
      if (.not. (ub > ua)) return
      u_first = ua; u_last = ub
      x1 = ua + c*(ub - ua); x2 = ub - c*(ub - ua)
      call solve(x1, s1)
      if (status /= wa_ok) return
      call solve(x2, s2)
      if (status /= wa_ok) return
      do it = 1, 100
         if (ub - ua <= tol) exit
         if (s1%p_star <= s2%p_star) then
            ub = x2; x2 = x1; s2 = s1
            x1 = ua + c*(ub - ua)
            call solve(x1, s1)
         else
            ua = x1; x1 = x2; s1 = s2
            x2 = ub - c*(ub - ua)
            call solve(x2, s2)
         end if
         if (status /= wa_ok) return
      end do
      ! an interior minimum only (both ends of the bracket moved), below the ends by more
      ! than the round-off of the point solves; else P* is monotone (or flat) over the
      ! range and its least value is the end's, a chain point
      if (ua == u_first .or. ub == u_last) return
      if (s2%p_star < s1%p_star) s1 = s2
      if (s1%p_star < s%p_star - 16.0_wp*epsilon(1.0_wp)*abs(s%p_star)) s = s1
   contains
      subroutine solve(u, st)
         real(wp), intent(in) :: u
         type(state_type), intent(out) :: st
         if (in_log) then
            call state_at_param(model, params, ch, i, exp(u), st, status, errmsg)
         else
            call state_at_param(model, params, ch, i, u, st, status, errmsg)
         end if
      end subroutine solve
   end subroutine floor_minimum

   ! ------------------------------------------- load-control jump energies

   !> The energy released by each jump of a load-controlled path (path_from_branch of the
   !> same branch): for a jump at load P0 from state 1 to state 2, the drop of the
   !> potential E + P0 gbar* (E: the stored energy, elastic and adhesive, dE = -P* dgbar*
   !> along equilibria) is  int_1^2 (P* - P0) dgbar*  along the branch from 1 to 2 through
   !> the states in between (doc/theory.md, "Gap control"); units p* Delta, per period.
   !> energy(k) is set at the jump-start events k whose next event is the landing (a jump
   !> end, or full contact reached); NaN at every other event, at a jump from separation
   !> (a* = 0: the separated state is not on the branch) and at a pull-off (the surfaces
   !> separate under a tensile load: the released energy is unbounded).
   subroutine load_jump_energies(model, params, branch, lpath, energy, status, errmsg)
      use, intrinsic :: ieee_arithmetic, only: ieee_quiet_nan
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      type(path_type), intent(in) :: lpath
      real(wp), intent(out) :: energy(:)
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(chain_type) :: ch
      type(cover_type) :: cov
      type(state_type) :: s1, s2
      real(wp) :: pos1, pos2
      integer :: k
      logical :: ok1, ok2

      status = wa_ok
      energy = ieee_value(1.0_wp, ieee_quiet_nan)
      if (size(energy) < lpath%n) then
         call set_error(wa_invalid_argument, "energy: needs one element per event of the "// &
            "path", status, errmsg)
         return
      end if
      call build_chain(model, params, branch, ch, status, errmsg)
      if (status /= wa_ok) return
      do k = 1, lpath%n - 1
         if (lpath%event(k) /= event_jump_start .or. .not. (lpath%event(k + 1) == &
            event_jump_end .or. lpath%event(k + 1) == event_full_contact_reached)) cycle
         if (lpath%a_star(k) <= 0.0_wp) cycle         ! from separation: off the branch
         call locate(lpath%a_star(k), lpath%c_star(k), lpath%p_star(k), pos1, s1, ok1)
         if (status /= wa_ok) return
         if (lpath%event(k + 1) == event_full_contact_reached) then
            ! full contact (gbar* = 0) at P0 above the chain's end: gbar* stays 0 from the
            ! end (a* = 1/2) to the landing, so the integral stops at the end
            pos2 = real(ch%n - 1, wp); s2 = chain_state(ch, ch%n); ok2 = .true.
         else
            call locate(lpath%a_star(k + 1), lpath%c_star(k + 1), lpath%p_star(k + 1), pos2, &
               s2, ok2)
            if (status /= wa_ok) return
         end if
         if (.not. (ok1 .and. ok2) .or. pos1 == pos2) cycle
         call build_cover(model, params, ch, [stretch_type(pos1, pos2)], n_gauss, 1, cov, &
            status, errmsg)
         if (status /= wa_ok) return
         ! energy_lost gives -int P* dgbar* along the stretch
         energy(k) = -energy_lost(cov, [stretch_type(pos1, pos2)]) - &
            lpath%p_star(k)*(s2%gbar - s1%gbar)
      end do
   contains
      !> The chain position of the state (a*, c*, P*) of the path, and the state there
      !> with its gbar*: the interval whose interpolated c* and P* at the state's
      !> parameter come nearest (ok = .false. if none is within 1e-2: the interpolation
      !> only picks the interval; the state there is solved at the state's parameter).
      subroutine locate(a, c, p, pos, st, ok)
         real(wp), intent(in) :: a, c, p
         real(wp), intent(out) :: pos
         type(state_type), intent(out) :: st
         logical, intent(out) :: ok
         type(state_type) :: guess
         real(wp) :: x, t, d, d_best, x0, x1
         integer :: i, kind
         ok = .false.
         pos = 0.0_wp
         d_best = 1.0e-2_wp
         guess%a_star = a; guess%c_star = c; guess%gap_width = c - a; guess%p_star = p
         guess%zone_case = zone_inside
         do i = 1, ch%n - 1
            kind = param_kind(ch, i)
            select case (kind)
            case (0)
               x = a
            case (1)
               x = c
            case (3)
               x = curve_variable(model, guess)
            case default
               cycle
            end select
            x0 = param(ch, i, 0.0_wp); x1 = param(ch, i, 1.0_wp)
            if ((x - x0)*(x - x1) > 0.0_wp) cycle
            t = 0.0_wp
            if (x1 /= x0) t = (x - x0)/(x1 - x0)
            d = abs(ch%c(i) + t*(ch%c(i + 1) - ch%c(i)) - c) + &
               abs(ch%p(i) + t*(ch%p(i + 1) - ch%p(i)) - p)
            if (d < d_best) then
               d_best = d; pos = real(i - 1, wp) + t; ok = .true.
            end if
         end do
         if (.not. ok) return
         i = min(int(pos), ch%n - 2) + 1
         t = pos - real(i - 1, wp)
         if (t <= 0.0_wp) then
            st = chain_state(ch, i)
         else if (t >= 1.0_wp) then
            st = chain_state(ch, i + 1)
         else
            call state_at_param(model, params, ch, i, param(ch, i, t), st, status, errmsg)
         end if
      end subroutine locate
   end subroutine load_jump_energies

end module wa_gappath
