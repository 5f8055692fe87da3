!> display: none
!>
!> The extrema of gbar* along the chain of a branch, where stability under gap control
!> changes (doc/theory.md, "Gap control"): smooth turns, located by Brent's minimisation
!> with the point solves of wa_chain and refined by a parabola-vertex step, and corners.
!> The last stretch (to full contact) is stable, so stability is the parity of the number
!> of gbar* extrema between a state and full contact. Turns that no traced point shows
!> (near a switch to c* = 1/2, below the tracer's first point) are sampled into the chain
!> first.
module wa_chain_extrema
   use wa_kinds, only: wp
   use wa_status, only: wa_ok
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_no_contact, zone_inside, model_md, model_dw
   use wa_curve, only: curve_variable, curve_weight, curve_y_max
   use wa_branch, only: event_switch
   use wa_roots, only: minimum_type, minimum_init, minimum_propose, minimum_accept
   use wa_chain, only: chain_type, chain_insert, chain_state, param_kind, param, &
      below_tracer, state_at_param, local_state, solve_at_y, solve_at_a
   implicit none
   private

   public :: sample_switch_intervals, sample_floor_intervals, locate_extrema

contains

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
      !> steps; wa_roots) to 1e-9 of the bracket, x to ~sqrt(eps) of it in any case (gbar*
      !> is flat there): the vertex refinement below does the rest. s: the state at x.
      subroutine brent_minimum(a_in, b_in, x)
         real(wp), intent(in) :: a_in, b_in
         real(wp), intent(out) :: x
         type(minimum_type) :: mn
         type(state_type) :: su
         real(wp) :: u
         logical :: done
         integer :: it
         call minimum_init(mn, a_in, b_in, 1.0e-9_wp*abs(b_in - a_in) + 1.0e-300_wp)
         do it = 1, 101                          ! the first point and 100 steps
            call minimum_propose(mn, u, done)
            if (done) exit
            call solve(u, su)
            if (status /= wa_ok) return
            call minimum_accept(mn, -sgn*su%gbar)
            if (mn%improved) s = su
         end do
         x = mn%x
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

end module wa_chain_extrema
