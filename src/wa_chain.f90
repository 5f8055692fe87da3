!> display: none
!>
!> The chain of a traced branch (gap control and the energies of load-controlled jumps):
!> the branch pieces joined into one curve from the first interaction (MD: the no-contact
!> family; other models: the a* -> 0 end of the contact curve) to full contact (a* = 1/2,
!> gbar* = 0), its parameter on each interval (a*, c*, gbar* or the curve variable y), and
!> the point solves that give the state of an interval at a value of its parameter.
module wa_chain
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_numerical_error, set_error
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_no_contact, zone_inside, zone_whole_period, &
      zone_full_contact, model_md, model_dw
   use wa_models, only: model_roots, max_model_roots
   use wa_separation, only: state_mean_gap, dw_state_gbar, md_state_gbar
   use wa_md_nocontact, only: md_no_contact_state
   use wa_curve, only: curve_residual, curve_state, curve_variable, curve_weight, &
      curve_case2_load
   use wa_branch, only: branch_type, event_switch, event_branch_end, event_none
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept
   implicit none
   private

   public :: chain_type, y_hint_type, stretch_type
   public :: build_chain, chain_insert, chain_state, param_kind, param, below_tracer
   public :: state_at_param, local_state, solve_at_y, solve_at_a

   !> The a* -> 0 end of a contact curve that does not join a no-contact state
   real(wp), parameter :: a_limit = 1.0e-15_wp

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


contains

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

   !> The parameter of chain interval i at t in [0, 1] (linear between its end points).
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

   !> The chain's point i as a state (a*, c*, P*, gbar*, zone case).
   pure function chain_state(ch, i) result(s)
      type(chain_type), intent(in) :: ch
      integer, intent(in) :: i
      type(state_type) :: s
      s%a_star = ch%a(i); s%c_star = ch%c(i); s%p_star = ch%p(i); s%gbar = ch%g(i)
      s%zone_case = ch%zone(i)
      s%gap_width = ch%c(i) - ch%a(i)                 ! c* - a* (wa_state)
   end function chain_state

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
      character(len=512) :: first_msg
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
      call solve_at_a(model, params, x, c_guess, zone, s, status, first_msg)
      if (status /= wa_ok .and. zone >= 0 .and. ch%zone(i) /= ch%zone(i + 1)) then
         ! an interval that changes zone case without a switch point between (a fold at
         ! the switch): the equilibrium nearest the guess in any case (the first
         ! attempt's message is dropped: a retry that succeeds leaves no stale message)
         call solve_at_a(model, params, x, c_guess, -1, s, status, errmsg)
      else if (status /= wa_ok .and. present(errmsg)) then
         errmsg = first_msg
      end if
   end subroutine state_at_param

   !> The state at a* = x on chain interval i (t: its position in the interval) without
   !> a root scan, where the interval allows: case 2 in closed form (c* = 1/2), case 1 of
   !> DW and MD by Brent on F(x, y) in y within the interval's y range (widened at most
   !> three times). done = .false.: not applicable here (the caller scans for roots).
   subroutine local_state(model, params, ch, i, x, t, s, done, status, errmsg, hint)
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

end module wa_chain
