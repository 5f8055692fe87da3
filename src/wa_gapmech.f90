!> Mechanisms of the gap-controlled (mean-gap) cycle, for the adhesion map (doc/theory.md,
!> "Adhesion map", gap control): how contact is made and full contact reached on the
!> approach, how contact is lost on the retraction. Both are read off the events of the
!> cycle of wa_gappath (without W*, panels or landing states' energies).
!>
!> Approach (map `which` = 3), a sum of two flags:
!>   1 when contact is made by a jump (a jump from a state without contact, P* = 0 far
!>     apart or MD's Dugdale zone around the crest, that lands on a state with contact),
!>   2 when the approach jumps from a state with contact (at a minimum of gbar*).
!> Retraction (which = 4):
!>   1 when contact is lost by a jump (from a maximum of gbar* on a state with contact to
!>     a state without contact or far apart), unless that maximum lies at a* < 1e-3
!>     (a_point_pull_off, as for the pull-off under load control): the contact has then
!>     shrunk to a point first and the loss counts as gradual. The maximum is born at
!>     a* -> 0 and moves exponentially fast with mu there, so the birth itself cannot be
!>     placed in double precision; a* = 1e-3 can, by the smooth ln(a*/1e-3),
!>   2 when the retraction jumps between states with contact before.
!> Jumps between states without contact (MD's jump from far apart at the first
!> interaction and back at the interaction lost, and any between crest-zone states) do not
!> count: MD has them for every mu > 0 (gbar* rises as c* ln(1/c*) from the first
!> interaction) and at small mu they are below the traced branch's resolution.
module wa_gapmech
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   use wa_kinds, only: wp
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   use wa_params, only: params_type, new_params
   use wa_state, only: zone_no_contact, zone_inside
   use wa_branch, only: branch_type, trace_branch
   use wa_mechanism, only: a_point_pull_off, mechanism_bisection, bisection_start, &
      bisection_next, bisection_tell, bisection_result
   use wa_gappath, only: gap_path_type, gap_stage_approach, gap_stage_retraction, &
      gap_event_jump_start, gap_event_jump_end
   use wa_gapcritical, only: gap_cycle_critical
   implicit none
   private

   public :: gap_mechanisms, gap_mechanisms_from_branch, gap_mechanism_change, &
      gap_mechanism_name
   public :: gap_flag_jump_contact, gap_flag_jumps_within

   !> The flags of a gap mechanism code (see the module header)
   integer, parameter :: gap_flag_jump_contact = 1, gap_flag_jumps_within = 2

contains

   !> "gradual", "jump-in", ... for mechanism m of the approach (which = 3) or the
   !> retraction (which = 4).
   pure function gap_mechanism_name(which, m) result(text)
      !> The stage, 3 (the approach) or 4 (the retraction), as the map's `which`
      integer, intent(in) :: which
      !> The mechanism code (0-3, a sum of gap_flag_* flags)
      integer, intent(in) :: m
      character(len=:), allocatable :: text
      character(len=*), parameter :: app(0:3) = [character(len=20) :: "gradual", &
         "jump-in", "gradual+inner jumps", "jump-in+inner jumps"]
      character(len=*), parameter :: ret(0:3) = [character(len=20) :: "gradual", &
         "jump-out", "inner jumps+gradual", "inner jumps+jump-out"]
      if (m < 0 .or. m > 3 .or. (which /= 3 .and. which /= 4)) then
         text = "unknown"
      else if (which == 3) then
         text = trim(app(m))
      else
         text = trim(ret(m))
      end if
   end function gap_mechanism_name

   !> Trace the branch at (alpha, mu) and classify its gap-controlled cycle.
   subroutine gap_mechanisms(model, params, mech_approach, mech_retraction, status, errmsg)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The approach's mechanism (0-3, see the module header; -1 when the cycle fails)
      integer, intent(out) :: mech_approach
      !> The retraction's mechanism (0-3; -1 when the cycle fails)
      integer, intent(out) :: mech_retraction
      !> wa_ok; else the status of the failing trace or cycle
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      type(branch_type) :: branch
      mech_approach = -1
      mech_retraction = -1
      call trace_branch(model, params, branch, status, errmsg)
      if (status /= wa_ok) return
      call gap_mechanisms_from_branch(model, params, branch, mech_approach, &
         mech_retraction, status, errmsg)
   end subroutine gap_mechanisms

   !> The approach and retraction mechanisms of the gap-controlled cycle on a traced branch
   !> (-1 both when the cycle fails).
   subroutine gap_mechanisms_from_branch(model, params, branch, mech_approach, &
         mech_retraction, status, errmsg, ln_a_out, g_in, g_half)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: branch
      integer, intent(out) :: mech_approach, mech_retraction
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      !> ln(a* / a_point_pull_off) at the maximum of gbar* from which the retraction leaves
      !> contact by a jump (NaN where it does not): the map's smooth indicator of the
      !> jump-out boundaries
      real(wp), intent(out), optional :: ln_a_out
      !> gbar* at the first traced state with contact (a* = a_start) minus gbar* of the
      !> approach's first jump from a state without contact (NaN where there is none): it
      !> changes sign where that jump's landing passes the onset of contact, the map's
      !> smooth indicator of the jump-in boundaries (contact made gradually <-> by a jump)
      real(wp), intent(out), optional :: g_in
      !> 1 - gbar* of the first approach (1) and retraction (2) jump between a case-1 state
      !> and a state at c* = 1/2 (NaN where there is none): on the c* = 1/2 sheet contact
      !> sets in at gbar* = 1 (a* -> 0, the zone over the whole period), so it changes sign
      !> where that jump's end on the sheet passes the onset of contact, the map's smooth
      !> indicator of those inner-jump boundaries
      real(wp), intent(out), optional :: g_half(2)
      type(gap_path_type) :: path
      real(wp) :: p_min, g_min, a_min, g_contact
      integer :: k
      logical :: from_contact, to_contact

      mech_approach = -1
      mech_retraction = -1
      if (present(ln_a_out)) ln_a_out = ieee_value(1.0_wp, ieee_quiet_nan)
      if (present(g_in)) g_in = ieee_value(1.0_wp, ieee_quiet_nan)
      if (present(g_half)) g_half = ieee_value(1.0_wp, ieee_quiet_nan)
      call gap_cycle_critical(model, params, branch, path, p_min, g_min, a_min, g_contact, &
         status, errmsg)
      if (status /= wa_ok) return
      mech_approach = 0
      mech_retraction = 0
      do k = 1, path%n - 1
         if (path%event(k) /= gap_event_jump_start .or. &
            path%event(k + 1) /= gap_event_jump_end) cycle
         from_contact = in_contact(k)
         to_contact = in_contact(k + 1)
         if (present(g_half) .and. (path%stage(k) == gap_stage_approach .or. &
            path%stage(k) == gap_stage_retraction)) then
            associate (g => g_half(merge(1, 2, path%stage(k) == gap_stage_approach)))
               if (ieee_is_nan(g) .and. one_half_one_case1(k)) g = 1.0_wp - path%gbar(k)
            end associate
         end if
         if (path%stage(k) == gap_stage_approach) then
            if (present(g_in) .and. .not. from_contact) then
               if (ieee_is_nan(g_in)) g_in = onset_gbar() - path%gbar(k)
            end if
            if (.not. from_contact .and. to_contact) &
               mech_approach = ior(mech_approach, gap_flag_jump_contact)
            if (from_contact .and. to_contact) &
               mech_approach = ior(mech_approach, gap_flag_jumps_within)
         else if (path%stage(k) == gap_stage_retraction) then
            if (from_contact .and. .not. to_contact) then
               if (present(ln_a_out)) ln_a_out = log(path%a_star(k)/a_point_pull_off)
               if (path%a_star(k) >= a_point_pull_off) &     ! else shrunk to a point
                  mech_retraction = ior(mech_retraction, gap_flag_jump_contact)
            end if
            ! jumps within contact before contact is lost (not after a regain)
            if (from_contact .and. to_contact .and. &
               iand(mech_retraction, gap_flag_jump_contact) == 0) &
               mech_retraction = ior(mech_retraction, gap_flag_jumps_within)
         end if
      end do
   contains
      pure real(wp) function onset_gbar()
         integer :: i
         onset_gbar = ieee_value(1.0_wp, ieee_quiet_nan)
         do i = 1, branch%n
            if (branch%a_star(i) > 0.0_wp .and. branch%zone_case(i) /= zone_no_contact) then
               onset_gbar = branch%gbar(i)
               return
            end if
         end do
      end function onset_gbar

      !> Jump k -> k+1 has one end at c* = 1/2 and the other on case 1
      pure logical function one_half_one_case1(k)
         integer, intent(in) :: k
         one_half_one_case1 = (path%c_star(k) == 0.5_wp .and. &
            path%zone_case(k + 1) == zone_inside) .or. &
            (path%c_star(k + 1) == 0.5_wp .and. path%zone_case(k) == zone_inside)
      end function one_half_one_case1

      pure logical function in_contact(k)
         integer, intent(in) :: k
         in_contact = path%a_star(k) > 0.0_wp .and. path%zone_case(k) /= zone_no_contact
      end function in_contact
   end subroutine gap_mechanisms_from_branch

   !> Bisect mu in [mu_lo, mu_hi] (mechanisms differ at the ends, else wa_no_solution) to
   !> where the gap approach (which = 3) or retraction (which = 4) mechanism changes, to
   !> 1e-10 relative (geometric bisection): the gap-control counterpart of mechanism_change; where the
   !> cycle fails at a trial mu, 14 other points of the bracket are tried in turn.
   subroutine gap_mechanism_change(model, alpha, which, mu_lo, mu_hi, mu_change, status, &
         errmsg, bracket)
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> The mechanism bisected, 3 (the approach's) or 4 (the retraction's)
      integer, intent(in) :: which
      !> The adhesion parameter alpha (valid range: new_params)
      real(wp), intent(in) :: alpha
      !> The lower end of the bracket in mu
      real(wp), intent(in) :: mu_lo
      !> The upper end of the bracket in mu (the mechanisms at the two ends differ)
      real(wp), intent(in) :: mu_hi
      !> The mu where the mechanism changes (NaN on failure)
      real(wp), intent(out) :: mu_change
      !> wa_ok; wa_invalid_argument for bad input; wa_no_solution when the mechanisms at the
      !> ends agree; else the status of the failing bisection
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
      character(len=*), intent(inout), optional :: errmsg
      !> The final bracket in mu that holds the change (NaN where none is known)
      real(wp), intent(out), optional :: bracket(2)
      real(wp), parameter :: tries(15) = [0.5_wp, 0.25_wp, 0.75_wp, 0.125_wp, 0.875_wp, &
         0.0625_wp, 0.9375_wp, 0.375_wp, 0.625_wp, 0.3125_wp, 0.6875_wp, 0.1875_wp, &
         0.8125_wp, 0.4375_wp, 0.5625_wp]
      type(mechanism_bisection) :: bis
      character(len=256) :: msg
      real(wp) :: mu
      integer :: mechanism, stat
      logical :: more

      mu_change = ieee_value(1.0_wp, ieee_quiet_nan)
      if (present(bracket)) bracket = mu_change
      status = wa_ok
      if (which /= 3 .and. which /= 4) then
         call set_error(wa_invalid_argument, "gap_mechanism_change: which must be 3 "// &
            "(approach) or 4 (retraction)", status, errmsg)
         return
      end if
      if (.not. (mu_lo > 0.0_wp .and. mu_hi > mu_lo)) then
         call set_error(wa_invalid_argument, "gap_mechanism_change: 0 < mu_lo < mu_hi "// &
            "required", status, errmsg)
         return
      end if
      call bisection_start(bis, mu_lo, mu_hi, tries, "gap cycle")
      do
         call bisection_next(bis, mu, more)
         if (.not. more) exit
         mechanism = gap_mechanism(model, alpha, mu, which, stat, msg)
         call bisection_tell(bis, mechanism, stat, msg)
      end do
      call bisection_result(bis, mu_change, status, errmsg, bracket)
   end subroutine gap_mechanism_change

   !> The approach (which = 3) or retraction (which = 4) mechanism of the gap cycle at
   !> (alpha, mu); -1 and stat /= wa_ok, with msg, where the cycle fails.
   integer function gap_mechanism(model, alpha, mu, which, stat, msg) result(mechanism)
      integer, intent(in) :: model, which
      real(wp), intent(in) :: alpha, mu
      integer, intent(out) :: stat
      character(len=*), intent(out) :: msg
      type(params_type) :: params
      integer :: ma, mr
      mechanism = -1
      msg = ""
      call new_params(alpha, mu, params, stat, msg)
      if (stat /= wa_ok) return
      call gap_mechanisms(model, params, ma, mr, stat, msg)
      if (stat /= wa_ok) return
      mechanism = merge(ma, mr, which == 3)
   end function gap_mechanism

end module wa_gapmech
