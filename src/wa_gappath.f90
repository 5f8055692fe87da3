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
   use wa_state, only: state_type, zone_no_contact
   use wa_branch, only: branch_type, trace_branch
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   use wa_validate, only: optval
   use wa_chain, only: chain_type, stretch_type, build_chain, chain_state, param, &
      state_at_param
   use wa_chain_extrema, only: sample_switch_intervals, sample_floor_intervals, locate_extrema
   use wa_chain_cover, only: cover_type, n_gauss, build_cover, energy_lost, law_on
   implicit none
   private

   public :: gap_path_type, gap_path, gap_path_from_branch, gap_law
   public :: gap_stage_approach, gap_stage_retraction
   public :: gap_event_jump_start, gap_event_jump_end, gap_event_full_contact_reached, &
      gap_event_full_contact_left, gap_event_touch, gap_event_contact_made, &
      gap_event_contact_lost, gap_event_interaction_lost
   public :: walk_cycle, max_walked

   integer, parameter :: gap_stage_approach = 1, gap_stage_retraction = 2
   !> Event codes of a gap-controlled path (3-6 as in wa_branch)
   integer, parameter :: gap_event_jump_start = 3, gap_event_jump_end = 4, &
      gap_event_full_contact_reached = 5, gap_event_full_contact_left = 6, &
      gap_event_touch = 10, gap_event_contact_made = 11, gap_event_contact_lost = 12, &
      gap_event_interaction_lost = 13
   integer, parameter :: max_events = 64, max_jumps = 15
   !> Walked stretches of one cycle, at most
   integer, parameter :: max_walked = 2*max_jumps + 4

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

contains

   !> Trace the branch, then follow approach and retraction under gap control.
   subroutine gap_path(model, params, path, status, errmsg)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The approach-retraction cycle: its events in order, W* and W*/(pi alpha^2/2), g_touch
      type(gap_path_type), intent(out) :: path
      !> wa_ok; else the status of the failing trace, walk or quadrature
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      character(len=:), allocatable :: caller_msg
      if (present(errmsg)) caller_msg = errmsg
      call trace_branch(model, params, branch, status, errmsg)
      if (status /= wa_ok) return
      call gap_path_from_branch(model, params, branch, path, status, errmsg)
      ! the message is the caller's on success, never that of a tolerated inner failure
      if (status == wa_ok .and. present(errmsg)) errmsg = caller_msg
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
      type(stretch_type) :: walked(max_walked)
      type(cover_type) :: cov
      integer :: n_walked, n_approach, n_nodes, n_splits

      call walk_cycle(model, params, branch, ch, path, walked, n_walked, n_approach, &
         status, errmsg)
      if (status /= wa_ok) return
      n_nodes = max(2, min(optval(nodes, n_gauss), 64))
      n_splits = max(1, min(optval(splits, 1), 64))
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
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The mean gaps gbar* (finite, >= 0)
      real(wp), intent(in) :: gbar(:)
      !> P* on the approach at each gbar(k) (size of gbar)
      real(wp), intent(out) :: p_approach(:)
      !> P* on the retraction at each gbar(k) (size of gbar)
      real(wp), intent(out) :: p_retract(:)
      !> dP*/dgbar* on the approach at each gbar(k) (size of gbar)
      real(wp), intent(out) :: dpdg_approach(:)
      !> dP*/dgbar* on the retraction at each gbar(k) (size of gbar)
      real(wp), intent(out) :: dpdg_retract(:)
      !> The energy lost per cycle W* (units p* Delta), as gap_path gives it
      real(wp), intent(out), optional :: w_star
      !> W*/(pi alpha^2/2), as gap_path gives it
      real(wp), intent(out), optional :: w_fraction
      !> wa_ok; wa_invalid_argument for a bad gbar or output size; else the status of the
      !> failing trace, walk or quadrature
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      type(chain_type) :: ch
      type(gap_path_type) :: path
      type(stretch_type) :: walked(max_walked)
      type(cover_type) :: cov
      integer :: n_walked, n_approach, k
      logical :: found
      character(len=:), allocatable :: caller_msg

      if (present(errmsg)) caller_msg = errmsg
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
      ! the message is the caller's on success, never that of a tolerated inner failure
      if (present(errmsg)) errmsg = caller_msg
   end subroutine gap_law

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

   !> Append the event of state s to the path (up to max_events).
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

end module wa_gappath
