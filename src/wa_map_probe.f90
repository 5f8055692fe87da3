!> display: none
!>
!> One point of the (alpha, mu) plane as the adhesion map sees it (a probe): the branch
!> traced at (alpha, mu), its load path's mechanisms under load and/or gap control, and
!> the smooth indicators whose zeros are the changes of mechanism (the difference of the
!> two loads whose order decides a mechanism, and the like), which wa_map_curve follows.
module wa_map_probe
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp
   use wa_status, only: wa_ok
   use wa_params, only: params_type, new_params
   use wa_state, only: zone_inside
   use wa_branch, only: branch_type, trace_branch, trace_options, event_pull_off
   use wa_curve, only: curve_residual, curve_y_max
   use wa_loadpath, only: path_type, path_from_branch, mechanism_snap
   use wa_mechanism, only: a_point_pull_off
   use wa_gapmech, only: gap_mechanisms_from_branch
   use wa_map_types, only: map_control_load, map_control_gap
   implicit none
   private

   public :: probe_type, probe, probe_indicator, first_indicator
   public :: ind_none, ind_loads

   !> One load path reduced to what the map needs: both mechanisms and the loads whose
   !> order decides them (NaN where absent).
   type :: probe_type
      integer :: status = wa_ok
      !> Full contact, pull-off (load control), approach, retraction (gap control); -1
      !> where not computed
      integer :: mech(4) = -1
      !> Full contact: 0 P* at a* -> 1/2, 1/2 largest maximum on case 1 / case 2, 3 zero
      real(wp) :: v_fc(0:3) = 0.0_wp
      !> Pull-off: 0 P* at a* -> 0, 1/2 lowest minimum on case 1 / case 2
      real(wp) :: v_pf(0:2) = 0.0_wp
      !> F(a_start, y_max): changes sign where a case-1 root is born at the branch's
      !> first point (the corner minimum of case 2 appears: gradual <-> jump case 2)
      real(wp) :: f_start = 0.0_wp
      !> ln(a* of the pull-off / a_point_pull_off) where contact is lost at a minimum
      !> (gradual <-> jump where the minimum passes a_point_pull_off)
      real(wp) :: ln_a_pf = 0.0_wp
      !> ln(a* / a_point_pull_off) at the maximum of gbar* from which the gap-controlled
      !> retraction jumps out of contact (gradual <-> jump-out where it passes 1e-3)
      real(wp) :: ln_a_out = 0.0_wp
      !> gbar* where contact sets in minus gbar* of the approach's first jump from a state
      !> without contact (gradual contact <-> jump-in where the landing passes the onset)
      real(wp) :: g_in = 0.0_wp
      !> 1 - gbar* of the first approach / retraction jump between case 1 and c* = 1/2
      !> (inner jumps <-> none where its end on the c* = 1/2 sheet passes the onset of
      !> contact, gbar* = 1)
      real(wp) :: g_half(2) = 0.0_wp
   end type probe_type

   !> The indicators a boundary can be followed by (the first whose signs differ across
   !> a located bracket is used for the next point's secant)
   integer, parameter :: ind_none = 0, ind_loads = 1, ind_f_start = 2, ind_a_pf = 3, &
      ind_a_out = 4, ind_g_in = 5, ind_g_half = 6

contains

   !> The indicator of kind ind (ind_*) at p for the change of mechanism `which` between ma
   !> (below) and mb (above): a smooth quantity that vanishes at the change (NaN where p
   !> lacks it or it does not apply to `which`).
   pure real(wp) function probe_indicator(p, ind, which, ma, mb) result(g)
      type(probe_type), intent(in) :: p
      integer, intent(in) :: ind, which, ma, mb
      select case (ind)
      case (ind_loads)
         g = load_indicator(p, which, ma, mb)
      case (ind_f_start)
         g = p%f_start
      case (ind_a_pf)
         g = p%ln_a_pf
         if (which /= 2) g = ieee_value(1.0_wp, ieee_quiet_nan)
      case (ind_a_out)
         g = p%ln_a_out
         if (which /= 4) g = ieee_value(1.0_wp, ieee_quiet_nan)
      case (ind_g_in)
         g = p%g_in
         if (which /= 3) g = ieee_value(1.0_wp, ieee_quiet_nan)
      case (ind_g_half)
         g = ieee_value(1.0_wp, ieee_quiet_nan)
         if (which == 3 .or. which == 4) g = p%g_half(which - 2)
      case default
         g = ieee_value(1.0_wp, ieee_quiet_nan)
      end select
   end function probe_indicator

   !> The first indicator (ind_*) of the change (which, ma -> mb) whose signs differ at the
   !> bracket ends p_lo, p_hi (ind_none if none does).
   pure integer function first_indicator(p_lo, p_hi, which, ma, mb) result(ind)
      type(probe_type), intent(in) :: p_lo, p_hi
      integer, intent(in) :: which, ma, mb
      real(wp) :: g_lo, g_hi
      do ind = ind_loads, ind_g_half
         g_lo = probe_indicator(p_lo, ind, which, ma, mb)
         g_hi = probe_indicator(p_hi, ind, which, ma, mb)
         if (ieee_is_finite(g_lo) .and. ieee_is_finite(g_hi) .and. &
            ((g_lo <= 0.0_wp .and. g_hi >= 0.0_wp) .or. (g_lo >= 0.0_wp .and. g_hi <= 0.0_wp)) &
            .and. g_lo /= g_hi) return
      end do
      ind = ind_none
   end function first_indicator

   !> The smooth quantity that vanishes where the mechanisms ma, mb of `which` change (NaN
   !> when this load path lacks one of the loads): for full contact the larger of the
   !> competing maximum loads minus the other (against a snap: the largest load of the
   !> curve, whose sign decides whether the curve crosses P* = 0); for pull-off the
   !> difference of the competing minimum loads (gradual: P* at a* -> 0).
   pure real(wp) function load_indicator(p, which, ma, mb) result(g)
      type(probe_type), intent(in) :: p
      integer, intent(in) :: which, ma, mb
      integer :: k
      if (which > 2) then                   ! gap control: no loads decide it
         g = ieee_value(1.0_wp, ieee_quiet_nan)
      else if (which == 1) then
         if (ma == mechanism_snap .or. mb == mechanism_snap) then
            g = -huge(1.0_wp)
            do k = 0, 2
               if (ieee_is_finite(p%v_fc(k))) g = max(g, p%v_fc(k))
            end do
         else
            g = p%v_fc(ma) - p%v_fc(mb)
         end if
      else
         g = p%v_pf(ma) - p%v_pf(mb)
      end if
   end function load_indicator

   !> Trace the branch at (alpha, exp(t)), follow the load path (control: map_control_*),
   !> keep the mechanisms and the competing loads; under gap control classify the
   !> gap-controlled cycle (wa_gapmech).
   subroutine probe(model, alpha, t, p, control)
      integer, intent(in) :: model, control
      real(wp), intent(in) :: alpha, t
      type(probe_type), intent(out) :: p
      type(params_type) :: params
      type(branch_type) :: br
      type(path_type) :: path
      type(trace_options) :: opts
      real(wp) :: nan
      integer :: i, n, zc
      character(len=256) :: msg

      msg = ""
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      p%v_fc = nan
      p%v_pf = nan
      p%f_start = nan
      p%ln_a_pf = nan
      p%ln_a_out = nan
      p%g_in = nan
      p%g_half = nan
      call new_params(alpha, exp(t), params, p%status, msg)
      if (p%status /= wa_ok) return
      opts%mean_gap = iand(control, map_control_gap) /= 0    ! load control needs P* only
      call trace_branch(model, params, br, p%status, msg, opts)
      if (p%status /= wa_ok) return
      ! a case-1 root born at the branch's first point changes the mechanisms of both
      ! controls (MD 302 and 402 at alpha ~0.03-0.2 under gap control)
      p%f_start = curve_residual(model, params, opts%a_start, curve_y_max)
      if (iand(control, map_control_gap) /= 0) then
         call gap_mechanisms_from_branch(model, params, br, p%mech(3), p%mech(4), p%status, &
            msg, ln_a_out=p%ln_a_out, g_in=p%g_in, g_half=p%g_half)
         if (p%status /= wa_ok) then
            p%mech = -1
            return
         end if
      end if
      if (iand(control, map_control_load) == 0) return
      call path_from_branch(model, params, br, path, p%status, msg, mechanisms_only=.true.)
      if (p%status /= wa_ok) then
         p%mech = -1
         return
      end if
      p%mech(1:2) = [path%fc_mechanism, path%pf_mechanism]
      do i = path%n, 1, -1
         if (path%event(i) /= event_pull_off) cycle
         if (path%a_star(i) >= opts%a_start) p%ln_a_pf = log(path%a_star(i)/a_point_pull_off)
         exit
      end do
      n = br%n
      p%v_fc(0) = br%p_star(n)
      p%v_fc(3) = 0.0_wp
      do i = 1, n                         ! the contact curve's a* -> 0 end (MD: after
         if (br%a_star(i) > 0.0_wp) then  ! the pieces without contact)
            p%v_pf(0) = br%p_star(i)
            exit
         end if
      end do
      do i = 2, n - 1
         zc = merge(1, 2, br%zone_case(i) == zone_inside)
         if (br%extremum(i) == 1) then
            if (.not. (p%v_fc(zc) >= br%p_star(i))) p%v_fc(zc) = br%p_star(i)
         else if (br%extremum(i) == -1) then
            if (.not. (p%v_pf(zc) <= br%p_star(i))) p%v_pf(zc) = br%p_star(i)
         end if
      end do
      if (n >= 2) then                    ! the end itself is a minimum of case 2
         if (br%p_star(n - 1) > br%p_star(n) .and. .not. (p%v_pf(2) <= br%p_star(n))) &
            p%v_pf(2) = br%p_star(n)
      end if
   end subroutine probe

end module wa_map_probe
