!> display: none
!>
!> Gauss-Legendre panels along the walked stretches of a chain (wa_chain): the chain cut
!> into pieces, smooth in their variable, each covered adaptively by panels that hold P*
!> and gbar* at their nodes. Shared by W* and the load-control jump energies (the
!> integrals int P* dgbar*) and by the gap law (the interpolants).
module wa_chain_cover
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_numerical_error, set_error
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside
   use wa_branch, only: event_switch, event_a_turn
   use wa_validate, only: optval
   use wa_math, only: sort_index
   use wa_quadrature, only: gl_rule_type, gl_rule, gl_interpolate, gl_value_slope, gl_invert
   use wa_chain, only: chain_type, y_hint_type, stretch_type, param_kind, param, &
      state_at_param
   implicit none
   private

   public :: cover_type, n_gauss, build_cover, energy_lost, law_on

   !> Gauss-Legendre nodes per quadrature panel
   integer, parameter :: n_gauss = 16

   !> The chain under the walked stretches cut into pieces (between consecutive walked
   !> ends and the nodes where the parameter changes kind or direction: smooth in their
   !> variable, gbar* monotone), each covered adaptively by Gauss-Legendre panels that
   !> hold P* and gbar* at their nodes. Shared by W* (the integrals) and the gap law
   !> (the interpolants).
   type :: cover_type
      type(gl_rule_type) :: rule
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
      call gl_rule(n_nodes, cov%rule)
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
      cuts(1:n_cuts) = cuts(sort_index(cuts(1:n_cuts)))
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
         if (optval(net_only, .false.)) then       ! W* only: skip what cancels
            if (sum([(merge(sign(1.0_wp, walked(k)%s2 - walked(k)%s1), &
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
      type(gl_rule_type), intent(in) :: rule
      real(wp), intent(in) :: f(:)
      real(wp) :: c(rule%n)
      c = matmul(rule%leg, f)
      tail = maxval(abs(c(rule%n - 2:rule%n)))
   end function legendre_tail

   pure logical function resolved(rule, f, tol_abs)
      type(gl_rule_type), intent(in) :: rule
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

   !> Append the panel [ua, ub] of values pv, gv and integral to the cover.
   subroutine store(cov, ua, ub, pv, gv, integral)
      type(cover_type), intent(inout) :: cov
      real(wp), intent(in) :: ua, ub, pv(:), gv(:), integral
      integer :: j
      if (cov%n_panels >= size(cov%u0)) call grow(cov, cov%rule%n, 2*size(cov%u0))
      cov%n_panels = cov%n_panels + 1
      j = cov%n_panels
      cov%u0(j) = ua; cov%u1(j) = ub
      cov%pv(:, j) = pv; cov%gv(:, j) = gv; cov%pint(j) = integral
      cov%g0(j) = gl_interpolate(cov%rule, gv, -1.0_wp)
      cov%g1(j) = gl_interpolate(cov%rule, gv, 1.0_wp)
   end subroutine store

   !> Enlarge the panel arrays of the cover to capacity panels of n_nodes nodes.
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
         z = gl_invert(cov%rule, cov%gv(:, best), g)
         call gl_value_slope(cov%rule, cov%pv(:, best), cov%gv(:, best), z, p_out, dpdg)
         return
      end do
   contains
      pure real(wp) function outside(x, a, b)
         real(wp), intent(in) :: x, a, b
         outside = max(0.0_wp, min(a, b) - x, x - max(a, b))
      end function outside
   end subroutine law_on

end module wa_chain_cover
