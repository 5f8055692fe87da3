!> The energy released by each jump of a load-controlled path (doc/theory.md, "Gap
!> control"): the integral of (P* - P0) dgbar* along the branch between the jump's ends,
!> by the Gauss-Legendre panels along the chain of the branch (src/wa_chain_cover.f90) that
!> also give W* under gap control. Load control's energies: gap control does not use it.
module wa_jump_energy
   use wa_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_status, only: wa_ok, wa_invalid_argument, set_error
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside
   use wa_curve, only: curve_variable
   use wa_branch, only: branch_type, event_jump_start, event_jump_end, &
      event_full_contact_reached
   use wa_loadpath, only: path_type
   use wa_chain, only: chain_type, stretch_type, build_chain, chain_state, param_kind, param, &
      state_at_param
   use wa_chain_cover, only: cover_type, n_gauss, build_cover, energy_lost
   implicit none
   private

   public :: load_jump_energies

contains

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
      !> The model: model_westergaard, model_jkr, model_dw or model_md
      integer, intent(in) :: model
      !> Validated dimensionless parameters alpha, mu (new_params)
      type(params_type), intent(in) :: params
      !> The traced branch (trace_branch) that lpath was built from
      type(branch_type), intent(in) :: branch
      !> The load-controlled path of that branch (path_from_branch)
      type(path_type), intent(in) :: lpath
      !> The energy released by the jump starting at each event (at least lpath%n
      !> elements); NaN where no jump starts or its energy is undefined
      real(wp), intent(out) :: energy(:)
      !> wa_ok; wa_invalid_argument when energy is too short; else the status of the
      !> failing point solve or quadrature
      integer, intent(out) :: status
      !> Receives the reason on failure (the bad argument and its valid range, or what failed)
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

end module wa_jump_energy
