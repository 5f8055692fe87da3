!> Continuation, load paths and critical forces (issue 3): folds, switches, agreement with
!> the point solver, the paper's section 4.1 statements, JKR facts.
module test_branch
   use wavyadhesion
   use wa_kinds, only: wp, pi
   use wa_md, only: md_load, md_opening
   use wa_dw, only: dw_residual
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_branch

contains

   subroutine collect_branch(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("branch_matches_point_solver", test_matches_points), &
         new_unittest("folds_have_zero_slope", test_folds), &
         new_unittest("switches_located", test_switches), &
         new_unittest("load_continuous_along_branch", test_continuity), &
         new_unittest("paper_alpha03_mu1_gradual_full_contact", test_paper_mu1), &
         new_unittest("paper_alpha03_mu5_snaps", test_paper_mu5), &
         new_unittest("small_mu_only_jump_in", test_small_mu), &
         new_unittest("jkr_full_contact_facts", test_jkr), &
         new_unittest("fold_matches_dense_scan", test_fold_scan), &
         new_unittest("md_branch_points_are_equilibria", test_md_points), &
         new_unittest("md_branch_folds_back_and_switches", test_md_shape), &
         new_unittest("md_case2_piece_reached", test_md_pieces), &
         new_unittest("invalid_model", test_invalid), &
         new_unittest("stability_matches_jacobian", test_stability), &
         new_unittest("md_returning_piece_unstable", test_md_returning_unstable)]
   end subroutine collect_branch

   type(params_type) function params_of(alpha, mu) result(params)
      real(wp), intent(in) :: alpha, mu
      integer :: status
      call new_params(alpha, mu, params, status)
   end function params_of

   type(branch_type) function traced(alpha, mu) result(b)
      real(wp), intent(in) :: alpha, mu
      integer :: status
      call trace_branch(model_dw, params_of(alpha, mu), b, status)
      if (status /= wa_ok) b%n = 0
   end function traced

   !> Every traced point is an equilibrium of the core solver, to 1e-12.
   subroutine test_matches_points(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: mus(3) = [1.0_wp, 2.5_wp, 5.0_wp]
      type(branch_type) :: b
      type(state_type) :: s
      integer :: i, j, status
      do j = 1, size(mus)
         b = traced(0.3_wp, mus(j))
         call check(error, b%n > 20, "trace failed")
         do i = 1, b%n
            ! switch points sit on the boundary to 1e-15 in a*, where c*(a*) is steep
            if (b%zone_case(i) == zone_full_contact .or. b%event(i) == event_switch) cycle
            call dw_equilibrium(params_of(0.3_wp, mus(j)), b%a_star(i), s, status)
            call check_close(error, b%c_star(i), s%c_star, 1.0e-12_wp, what="c*")
            call check_close(error, b%p_star(i), s%p_star, 1.0e-12_wp, 1.0e-12_wp, "P*")
         end do
      end do
   end subroutine test_matches_points

   !> At each fold the slope of P*(a*) from the point solver (Richardson-extrapolated
   !> central differences) vanishes: |dP*/da*| / |d2P*/da*2| <= 1e-10 places it in a*.
   subroutine test_folds(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      real(wp) :: a, d1, d2
      integer :: i, nfold
      b = traced(0.3_wp, 5.0_wp)
      nfold = 0
      do i = 1, b%n
         if (b%event(i) /= event_fold) cycle
         nfold = nfold + 1
         a = b%a_star(i)
         d1 = slope(0.3_wp, 5.0_wp, a, 1.0e-4_wp)
         d2 = (slope(0.3_wp, 5.0_wp, a + 1.0e-4_wp, 1.0e-5_wp) - &
            slope(0.3_wp, 5.0_wp, a - 1.0e-4_wp, 1.0e-5_wp))/2.0e-4_wp
         call check(error, abs(d1/d2) <= 1.0e-10_wp, "fold not at dP/da = 0")
         call check(error, b%extremum(i) == merge(1, -1, d2 < 0.0_wp), "fold kind")
      end do
      call check(error, nfold == 2, "alpha 0.3, mu 5 has two folds")
   end subroutine test_folds

   real(wp) function slope(alpha, mu, a, h)
      real(wp), intent(in) :: alpha, mu, a, h
      real(wp) :: d_h, d_h2
      d_h = (load(a + h) - load(a - h))/(2*h)
      d_h2 = (load(a + h/2) - load(a - h/2))/h
      slope = (4*d_h2 - d_h)/3
   contains
      real(wp) function load(x)
         real(wp), intent(in) :: x
         type(state_type) :: s
         integer :: status
         call dw_equilibrium(params_of(alpha, mu), x, s, status)
         load = s%p_star
      end function load
   end function slope

   !> A switch event sits where the point solver changes zone case (bisection to 1e-14).
   subroutine test_switches(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      type(state_type) :: lo, hi
      integer :: i, status, nswitch
      b = traced(0.6_wp, 1.0_wp)
      nswitch = 0
      do i = 1, b%n
         if (b%event(i) /= event_switch) cycle
         nswitch = nswitch + 1
         call dw_equilibrium(params_of(0.6_wp, 1.0_wp), b%a_star(i) - 1.0e-12_wp, lo, status)
         call dw_equilibrium(params_of(0.6_wp, 1.0_wp), b%a_star(i) + 1.0e-12_wp, hi, status)
         call check(error, lo%zone_case /= hi%zone_case, "switch not within 1e-12 in a*")
      end do
      call check(error, nswitch == 1, "alpha 0.6, mu 1: one case switch")
   end subroutine test_switches

   subroutine test_continuity(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      b = traced(0.3_wp, 2.5_wp)
      call check(error, maxval(abs(b%p_star(2:b%n) - b%p_star(1:b%n - 1))) < 0.02_wp, &
         "P* jumps between consecutive points")
      call check(error, all(b%a_star(2:b%n) >= b%a_star(1:b%n - 1)), "DW branch is a graph in a*")
   end subroutine test_continuity

   !> Paper section 4.1, alpha = 0.3, mu = 1: full contact reached gradually.
   subroutine test_paper_mu1(error)
      type(error_type), allocatable, intent(out) :: error
      type(path_type) :: path
      type(params_type) :: params
      integer :: status
      params = params_of(0.3_wp, 1.0_wp)
      call load_path(model_dw, params, path, status)
      call check(error, status == wa_ok, "status")
      call check(error, path%fc_mechanism == mechanism_gradual, "full contact not gradual")
      call check_close(error, path%p_fc, 1.0_wp - 0.5_wp*params%sigma0, &
         1.0e-14_wp, what="P_fc = 1 - Sigma0/2")
   end subroutine test_paper_mu1

   !> Paper section 4.1, alpha = 0.3, mu = 5: snapping into full contact (C -> D) and
   !> snapping detachment (F -> G) from the case-2 piece.
   subroutine test_paper_mu5(error)
      type(error_type), allocatable, intent(out) :: error
      type(path_type) :: path
      integer :: status
      call load_path(model_dw, params_of(0.3_wp, 5.0_wp), path, status)
      call check(error, status == wa_ok, "status")
      call check(error, path%fc_mechanism == mechanism_jump_case1, "no snap into full contact")
      call check(error, path%pf_mechanism == mechanism_jump_case2, "no snapping detachment")
      call check(error, path%p_pf < 0.0_wp .and. path%p_fc > 0.0_wp, "signs of P_fc, P_pf")
   end subroutine test_paper_mu5

   !> mu -> 0: the only jump is the jump-in; contact is lost gradually.
   subroutine test_small_mu(error)
      type(error_type), allocatable, intent(out) :: error
      type(path_type) :: path
      integer :: status
      call load_path(model_dw, params_of(0.3_wp, 1.0e-3_wp), path, status)
      call check(error, status == wa_ok, "status")
      call check(error, count(path%event(1:path%n) == event_jump_start) == 1, "extra jumps")
      call check(error, path%pf_mechanism == mechanism_gradual, "pull-off not gradual")
   end subroutine test_small_mu

   !> JKR: above alpha = (3/4)^(3/4)/sqrt(2) = 0.56988 full contact at zero load; below it
   !> P_fc is the local maximum of the JKR curve; P_pf = -Infinity.
   subroutine test_jkr(error)
      type(error_type), allocatable, intent(out) :: error
      type(path_type) :: path
      real(wp) :: alpha_c
      integer :: status
      alpha_c = 0.75_wp**0.75_wp/sqrt(2.0_wp)
      call load_path(model_jkr, params_of(alpha_c*1.001_wp, 1.0_wp), path, status)
      call check(error, status == wa_ok .and. path%p_fc == 0.0_wp .and. &
         path%fc_mechanism == mechanism_snap, "above 0.56988: snap at P* = 0")
      call check(error, path%p_pf < -huge(1.0_wp), "JKR pull-off is -Infinity")
      call load_path(model_jkr, params_of(0.5_wp, 1.0_wp), path, status)
      call check_close(error, path%p_fc, jkr_max(0.5_wp), 1.0e-12_wp, what="P_fc = JKR maximum")
   end subroutine test_jkr

   !> Local maximum of sin^2(pi a) - alpha sqrt(tan(pi a)) by golden section.
   real(wp) function jkr_max(alpha)
      real(wp), intent(in) :: alpha
      real(wp) :: lo, hi, x1, x2
      integer :: k
      lo = 0.05_wp; hi = 0.45_wp
      do k = 1, 200
         x1 = hi - 0.618033988749895_wp*(hi - lo)
         x2 = lo + 0.618033988749895_wp*(hi - lo)
         if (jkr_load(alpha, x1) > jkr_load(alpha, x2)) then
            hi = x2
         else
            lo = x1
         end if
      end do
      jkr_max = jkr_load(alpha, 0.5_wp*(lo + hi))
   end function jkr_max

   !> The maximum fold of alpha 0.3, mu 5 agrees with the largest P* of a dense scan of
   !> the point solver (2001 points over +-1e-4) to the scan's spacing.
   subroutine test_fold_scan(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      type(state_type) :: s
      real(wp) :: a_fold, a, best_a, best_p
      integer :: i, status
      b = traced(0.3_wp, 5.0_wp)
      a_fold = -1
      do i = 1, b%n
         if (b%event(i) == event_fold .and. b%extremum(i) == 1) a_fold = b%a_star(i)
      end do
      call check(error, a_fold > 0, "no maximum fold")
      if (allocated(error)) return
      best_p = -huge(1.0_wp)
      best_a = 0
      do i = -1000, 1000
         a = a_fold + 1.0e-7_wp*i
         call dw_equilibrium(params_of(0.3_wp, 5.0_wp), a, s, status)
         if (s%p_star > best_p) then
            best_p = s%p_star; best_a = a
         end if
      end do
      call check(error, abs(best_a - a_fold) <= 1.0e-7_wp, "fold far from the scan's maximum")
   end subroutine test_fold_scan

   !> Every case-1 point of an MD branch is one of md_roots' states at its a*, to 1e-12.
   subroutine test_md_points(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      type(state_type) :: states(4)
      integer :: i, n, status
      call trace_branch(model_md, params_of(0.3_wp, 1.0_wp), b, status)
      call check(error, status == wa_ok .and. b%n > 50, "md trace failed")
      if (allocated(error)) return
      do i = 1, b%n
         ! events and a*-turning points (a double root there) are checked elsewhere
         if (b%zone_case(i) /= zone_inside .or. b%event(i) /= event_none .or. &
            b%extremum(i) /= 0) cycle
         call md_roots(params_of(0.3_wp, 1.0_wp), b%a_star(i), states, n, status)
         call check(error, status == wa_ok, "md_roots status")
         call check(error, minval(abs(states(1:n)%c_star - b%c_star(i))) <= 1.0e-12_wp &
            *b%c_star(i), "branch point is not an MD equilibrium")
         if (allocated(error)) return
      end do
   end subroutine test_md_points

   !> MD alpha 0.3, mu 1 (doc/theory.md, "Continuation": the curve folds back in a*): a* decreases somewhere
   !> along the case-1 curve, which ends on c* = 1/2 at a corner minimum.
   subroutine test_md_shape(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      integer :: i, status, k
      call trace_branch(model_md, params_of(0.3_wp, 1.0_wp), b, status)
      call check(error, any(b%a_star(2:b%n) < b%a_star(1:b%n - 1)), "no fold back in a*")
      k = 0
      do i = 1, b%n
         if (b%event(i) == event_switch) k = i
      end do
      call check(error, k > 0, "no case switch")
      if (allocated(error)) return
      call check(error, b%extremum(k) == -1, "the switch is not a corner minimum")
      call check(error, b%zone_case(b%n) == zone_full_contact, "branch does not end at a* = 1/2")
   end subroutine test_md_shape

   !> MD alpha 10, mu 10: the case-1 sheets start and end at a* -> 0, case 2 holds at every
   !> a* and is a piece of its own; unloading follows it down to a* -> 0 (P_pf = -Sigma0).
   subroutine test_md_pieces(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      type(path_type) :: path
      type(params_type) :: params
      integer :: status
      params = params_of(10.0_wp, 10.0_wp)
      call trace_branch(model_md, params, b, status)
      call check(error, status == wa_ok .and. b%a_star(b%n) == 0.5_wp, "no piece reaches 1/2")
      call check(error, count(b%event(1:b%n) == event_branch_end) >= 4, "expected several pieces")
      call load_path(model_md, params, path, status)
      call check(error, status == wa_ok .and. path%pf_mechanism == mechanism_gradual, "pull-off")
      call check_close(error, path%p_pf, -params%sigma0, 1.0e-12_wp, what="P_pf = -Sigma0")
      call check(error, path%p_fc == 0.0_wp .and. path%fc_mechanism == mechanism_snap, "P_fc")
   end subroutine test_md_pieces

   subroutine test_invalid(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      character(len=256) :: msg
      integer :: status
      msg = ""
      call trace_branch(7, params_of(0.3_wp, 1.0_wp), b, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "model") > 0, trim(msg))
      block
         type(params_type) :: bad
         type(path_type) :: path
         bad%alpha = -1.0_wp
         bad%mu = 1.0_wp
         msg = ""
         call trace_branch(model_dw, bad, b, status, msg)
         call check(error, status == wa_invalid_argument .and. index(msg, "alpha") > 0, trim(msg))
         call load_path(model_md, bad, path, status)
         call check(error, status == wa_invalid_argument, "load_path: bad alpha accepted")
      end block
   end subroutine test_invalid

   !> The stability flag against an independent criterion (doc/theory.md, "Stability under
   !> load control"): on case 1 a state is stable iff D = dP/da* dG/dc* - dP/dc* dG/da* > 0,
   !> G the equilibrium equation in (a*, c*) (MD: the opening (2.27b) - Dcod with P* from
   !> (2.27a); DW: ln of (2.25b)), by central differences of the point formulas, not the
   !> tracer's partials; on case 2 iff dP*/da* > 0. Points where D is below 1e-6 of its
   !> terms (at and next to folds) and extrema are skipped.
   subroutine test_stability(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: alphas(4) = [0.1_wp, 0.3_wp, 1.0_wp, 3.0_wp]
      real(wp), parameter :: mus(4) = [0.3_wp, 1.0_wp, 5.0_wp, 30.0_wp]
      integer, parameter :: models(2) = [model_dw, model_md]
      type(params_type) :: p
      type(branch_type) :: b
      integer :: i, j, k, m, status, checked
      real(wp) :: d, scale
      character(len=160) :: text
      checked = 0
      do m = 1, 2
         do i = 1, size(alphas)
            do j = 1, size(mus)
               p = params_of(alphas(i), mus(j))
               call trace_branch(models(m), p, b, status)
               call check(error, status == wa_ok, "trace")
               if (allocated(error)) return
               do k = 1, b%n
                  if (b%extremum(k) == 1 .or. b%extremum(k) == -1) cycle
                  if (b%zone_case(k) == zone_whole_period) then
                     call check(error, b%stable(k), "case 2 (dP*/da* > 0) flagged unstable")
                     cycle
                  end if
                  if (b%zone_case(k) /= zone_inside) cycle
                  if (b%c_star(k) >= 0.5_wp - 1.0e-9_wp .or. b%a_star(k) < 1.0e-4_wp) cycle
                  call jacobian(models(m), p, b%a_star(k), b%c_star(k), d, scale)
                  if (abs(d) < 1.0e-6_wp*scale) cycle
                  checked = checked + 1
                  write (text, '(a,i0,a,2es10.2,a,2es12.4,a,l1)') "model ", models(m), &
                     " alpha, mu", alphas(i), mus(j), ": a*, D", b%a_star(k), d, " stable ", &
                     b%stable(k)
                  call check(error, (d > 0.0_wp) .eqv. b%stable(k), trim(text))
                  if (allocated(error)) return
               end do
            end do
         end do
      end do
      call check(error, checked > 2000, "too few points checked")
   end subroutine test_stability

   !> D = P_a G_c - P_c G_a at (a*, c*) by central differences, and |P_a G_c| + |P_c G_a|.
   subroutine jacobian(model, p, a, c, d, scale)
      integer, intent(in) :: model
      type(params_type), intent(in) :: p
      real(wp), intent(in) :: a, c
      real(wp), intent(out) :: d, scale
      real(wp) :: h, pa, pc, ga, gc
      h = 1.0e-6_wp*min(a, c - a, 0.5_wp - c)
      pa = (load(a + h, c) - load(a - h, c))/(2.0_wp*h)
      pc = (load(a, c + h) - load(a, c - h))/(2.0_wp*h)
      ga = (eqn(a + h, c) - eqn(a - h, c))/(2.0_wp*h)
      gc = (eqn(a, c + h) - eqn(a, c - h))/(2.0_wp*h)
      d = pa*gc - pc*ga
      scale = abs(pa*gc) + abs(pc*ga)
   contains
      real(wp) function load(x, y)
         real(wp), intent(in) :: x, y
         if (model == model_md) then
            load = md_load(p, x, y - x)
         else
            load = sin(pi*x)**2 - 0.5_wp*p%sigma0*sqrt(sin(pi*(y - x))*sin(pi*(y + x))) &
               /cos(pi*x)
         end if
      end function load
      real(wp) function eqn(x, y)
         real(wp), intent(in) :: x, y
         if (model == model_md) then
            eqn = md_opening(p, x, y - x) - p%dcod
         else
            eqn = dw_residual(p, x, log((sin(pi*y) - sin(pi*x))/(1.0_wp - sin(pi*x))))
         end if
      end function eqn
   end subroutine jacobian

   !> alpha = 0.3, mu = 1 (doc/figures/branch_md_alpha0.3_mu1.png): past the load maximum
   !> the MD curve turns back in a* (event 9, not a fold) and returns to the switch to
   !> c* = 1/2; that whole returning piece is unstable, and the a*-turn leaves the flag as is.
   subroutine test_md_returning_unstable(error)
      type(error_type), allocatable, intent(out) :: error
      type(branch_type) :: b
      integer :: status, i_max, i_turn, i_switch, i
      call trace_branch(model_md, params_of(0.3_wp, 1.0_wp), b, status)
      call check(error, status == wa_ok, "trace")
      if (allocated(error)) return
      i_max = findloc(b%extremum(1:b%n), 1, dim=1)
      i_turn = findloc(b%event(1:b%n), event_a_turn, dim=1)
      i_switch = findloc(b%event(1:b%n), event_switch, dim=1)
      call check(error, 0 < i_max .and. i_max < i_turn .and. i_turn < i_switch, &
         "maximum, then a*-turn, then switch")
      if (allocated(error)) return
      call check(error, b%extremum(i_turn) == 2 .and. .not. b%stable(i_turn), "a*-turn unstable")
      call check(error, .not. any(b%stable(i_max:i_switch)), "returning piece unstable")
      call check(error, all(b%stable(i_switch + 1:b%n)), "case 2 after the corner stable")
      do i = 2, i_max - 1
         if (b%a_star(i) > 0.05_wp) call check(error, b%stable(i), "rising piece stable")
      end do
   end subroutine test_md_returning_unstable

end module test_branch
