!> Gap control (src/wa_gappath.f90): the identities of issue 11 and doc/theory.md
!> "Gap control": Westergaard has no hysteresis (W* = 0) and its approach curve is
!> gbar* = 1 - P* + P* ln P*; W* -> 0 as mu -> 0 for DW; W* >= 0; every jump starts
!> where gbar* is extremal and keeps gbar*; the quadrature of W* is converged; every
!> load-control jump that lands on the branch releases a finite energy >= 0.
module test_gappath
   use wavyadhesion
   use wa_kinds, only: wp
   use wa_gappath, only: gap_path_from_branch
   use harness, only: error_type, unittest_type, new_unittest, check, check_close
   implicit none
   private

   public :: collect_gappath

contains

   subroutine collect_gappath(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest("westergaard_no_hysteresis", test_westergaard), &
         new_unittest("westergaard_approach_curve", test_westergaard_curve), &
         new_unittest("dw_energy_vanishes_with_mu", test_dw_mu_to_zero), &
         new_unittest("energy_nonnegative", test_nonnegative), &
         new_unittest("jumps_at_gbar_extrema", test_jumps), &
         new_unittest("md_event_sequence", test_md_events), &
         new_unittest("dw_quadrature_converged", test_dw_quadrature), &
         new_unittest("md_quadrature_converged", test_md_quadrature), &
         new_unittest("westergaard_gap_law", test_westergaard_law), &
         new_unittest("gap_law_loop_is_the_energy", test_law_energy), &
         new_unittest("gap_law_bad_input", test_law_bad_input), &
         new_unittest("load_jump_energies", test_load_jump_energies), &
         new_unittest("md_gbar_pair_before_switch", test_pair_before_switch)]
   end subroutine collect_gappath

   subroutine path_of(model, alpha, mu, path, error)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu
      type(gap_path_type), intent(out) :: path
      type(error_type), allocatable, intent(inout) :: error
      type(params_type) :: params
      integer :: status
      character(len=256) :: msg
      msg = ""
      call new_params(alpha, mu, params, status)
      call gap_path(model, params, path, status, msg)
      call check(error, status == wa_ok, "gap_path failed: "//trim(msg))
   end subroutine path_of

   subroutine test_westergaard(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_path_type) :: path
      call path_of(model_westergaard, 0.3_wp, 1.0_wp, path, error)
      if (allocated(error)) return
      call check_close(error, path%w_star, 0.0_wp, 0.0_wp, what="Westergaard W*")
      if (allocated(error)) return
      call check(error, count(path%event(1:path%n) == 3) == 0, "Westergaard: no jumps")
      if (allocated(error)) return
      call check(error, path%event(1) == gap_event_touch .and. path%gbar(1) == 1.0_wp, &
         "touch at gbar* = 1")
   end subroutine test_westergaard

   subroutine test_westergaard_curve(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(branch_type) :: b
      integer :: status, i
      real(wp) :: p
      call new_params(0.3_wp, 1.0_wp, params, status)
      call trace_branch(model_westergaard, params, b, status)
      do i = 1, b%n
         p = b%p_star(i)
         if (p <= 0.0_wp) cycle
         call check(error, abs(b%gbar(i) - (1.0_wp - p + p*log(p))) <= 1.0e-14_wp, &
            "Westergaard gbar* = 1 - P* + P* ln P*")
         if (allocated(error)) return
      end do
   end subroutine test_westergaard_curve

   subroutine test_dw_mu_to_zero(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_path_type) :: p1, p2, p3
      call path_of(model_dw, 0.3_wp, 1.0_wp, p1, error)
      call path_of(model_dw, 0.3_wp, 0.1_wp, p2, error)
      call path_of(model_dw, 0.3_wp, 1.0e-3_wp, p3, error)
      if (allocated(error)) return
      call check(error, p3%w_star < p2%w_star .and. p2%w_star < p1%w_star .and. &
         p3%w_star < 1.0e-5_wp*p1%w_star, "DW: W* falls to 0 with mu")
   end subroutine test_dw_mu_to_zero

   subroutine test_nonnegative(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_path_type) :: path
      real(wp), parameter :: alphas(2) = [0.3_wp, 1.0_wp], mus(3) = [0.3_wp, 1.0_wp, 5.0_wp]
      integer :: model, i, j
      do model = model_dw, model_md
         do i = 1, size(alphas)
            do j = 1, size(mus)
               call path_of(model, alphas(i), mus(j), path, error)
               if (allocated(error)) return
               call check(error, path%w_star > 0.0_wp, "W* > 0 with adhesion")
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_nonnegative

   !> A jump keeps gbar*; where it leaves a contact state, gbar* of the neighbouring
   !> equilibria (a* +- 1e-4, nearest c*) does not go beyond the jump's in the direction
   !> of travel (gbar* is extremal there).
   subroutine test_jumps(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_path_type) :: path
      type(params_type) :: params
      type(state_type) :: roots(8)
      real(wp) :: g, gn, d_best, sgn
      integer :: model, k, side, n, r, best, status
      do model = model_dw, model_md
         call path_of(model, 0.3_wp, 1.0_wp, path, error)
         if (allocated(error)) return
         call new_params(0.3_wp, 1.0_wp, params, status)
         do k = 1, path%n - 1
            if (path%event(k) /= 3) cycle
            call check(error, path%event(k + 1) == 4, "jump start followed by its end")
            if (allocated(error)) return
            call check_close(error, path%gbar(k + 1), path%gbar(k), 1.0e-12_wp, &
               what="a jump keeps gbar*")
            if (allocated(error)) return
            if (path%zone_case(k) /= zone_inside .or. path%c_star(k) > 0.5_wp - 1.0e-6_wp) cycle
            g = path%gbar(k)
            sgn = merge(1.0_wp, -1.0_wp, path%stage(k) == gap_stage_approach)  ! minimum
            do side = -1, 1, 2
               call model_roots(model, params, path%a_star(k) + side*1.0e-4_wp, roots, n, status)
               best = 1
               d_best = huge(1.0_wp)
               do r = 1, min(n, 8)
                  if (abs(roots(r)%c_star - path%c_star(k)) < d_best) then
                     d_best = abs(roots(r)%c_star - path%c_star(k)); best = r
                  end if
               end do
               call state_mean_gap(model, params, roots(best), gn, status)
               call check(error, sgn*(gn - g) >= -1.0e-12_wp, "jump starts at a gbar* extremum")
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_jumps

   !> MD alpha 0.036123: the fold of P* lies within 1e-13 in a* of the switch to c* = 1/2
   !> while c* still runs from 0.4977 to 1/2, and gbar* turns twice in that one interval
   !> of the trace (a pair, 1e-5 high). Without the interval's samples the inner jumps of
   !> the gap cycle vanished at mu = 0.01805 and 0.01808 and came back at 0.0181.
   subroutine test_pair_before_switch(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: mus(4) = [0.018_wp, 0.01805_wp, 0.01808_wp, 0.0181_wp]
      type(params_type) :: params
      integer :: k, status, ma, mr
      character(len=80) :: what
      do k = 1, size(mus)
         call new_params(0.036123_wp, mus(k), params, status)
         call gap_mechanisms(model_md, params, ma, mr, status)
         write (what, '(a,f8.5)') "MD alpha 0.036123 inner jumps both ways at mu ", mus(k)
         call check(error, status == wa_ok .and. ma == 2 .and. mr == 2, trim(what))
         if (allocated(error)) return
      end do
   end subroutine test_pair_before_switch

   subroutine test_md_events(error)
      type(error_type), allocatable, intent(out) :: error
      type(gap_path_type) :: path
      integer, parameter :: expected(14) = [10, 3, 4, 11, 3, 4, 5, 6, 3, 4, 12, 3, 4, 13]
      call path_of(model_md, 0.3_wp, 1.0_wp, path, error)
      if (allocated(error)) return
      call check(error, path%n == size(expected), "MD alpha 0.3 mu 1: 14 events")
      if (allocated(error)) return
      call check(error, all(path%event(1:path%n) == expected), "MD event sequence")
      if (allocated(error)) return
      ! first interaction at gbar* = 1 + 2 Dcod
      call check_close(error, path%gbar(1), 1.0_wp + 2.0_wp*0.15939878537739166_wp, &
         1.0e-14_wp, what="first interaction")
   end subroutine test_md_events

   !> W* with 12 Gauss nodes per chain interval against 20 nodes on halved intervals.
   subroutine test_dw_quadrature(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(branch_type) :: b
      type(gap_path_type) :: p1, p2
      integer :: status, k
      real(wp), parameter :: cases(2, 3) = reshape([0.3_wp, 1.0_wp, 0.3_wp, 0.1_wp, &
         1.0_wp, 5.0_wp], [2, 3])
      do k = 1, size(cases, 2)
         call new_params(cases(1, k), cases(2, k), params, status)
         call trace_branch(model_dw, params, b, status)
         call gap_path_from_branch(model_dw, params, b, p1, status)
         call gap_path_from_branch(model_dw, params, b, p2, status, nodes=20, splits=2)
         call check_close(error, p1%w_star, p2%w_star, 1.0e-11_wp, what="DW W* quadrature")
         if (allocated(error)) return
      end do
   end subroutine test_dw_quadrature

   !> The same for MD, where case-1 intervals near an a*-turn use the curve variable.
   subroutine test_md_quadrature(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(branch_type) :: b
      type(gap_path_type) :: p1, p2
      integer :: status, k
      ! (alpha 10, mu 3.1623: the point solves carry noise of 1e-13 of P*; the panels
      ! there were bisected to the limit and the path failed after ~1 s)
      real(wp), parameter :: cases(3, 6) = reshape([0.3_wp, 1.0_wp, 1.0e-11_wp, &
         0.3_wp, 5.0_wp, 1.0e-11_wp, 1.0_wp, 1.0_wp, 1.0e-11_wp, 0.6_wp, 1.0_wp, 1.0e-11_wp, &
         1.0_wp, 0.3_wp, 1.0e-11_wp, 10.0_wp, 3.1623_wp, 1.0e-11_wp], [3, 6])
      do k = 1, size(cases, 2)
         call new_params(cases(1, k), cases(2, k), params, status)
         call trace_branch(model_md, params, b, status)
         call gap_path_from_branch(model_md, params, b, p1, status)
         call check(error, status == wa_ok, "MD gap path")
         if (allocated(error)) return
         call gap_path_from_branch(model_md, params, b, p2, status, nodes=20, splits=2)
         call check_close(error, p1%w_star, p2%w_star, cases(3, k), what="MD W* quadrature")
         if (allocated(error)) return
      end do
   end subroutine test_md_quadrature

   !> gap_law for Westergaard: approach = retraction, gbar* = 1 - P* + P* ln P*, and
   !> dP*/dgbar* = 1/ln P*.
   subroutine test_westergaard_law(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      integer, parameter :: n = 41
      real(wp) :: g(n), pa(n), pr(n), da(n), dr(n), p
      integer :: status, k
      call new_params(0.3_wp, 1.0_wp, params, status)
      g = [(1.2_wp*real(k - 1, wp)/real(n - 1, wp), k = 1, n)]
      call gap_law(model_westergaard, params, g, pa, pr, da, dr, status)
      call check(error, status == wa_ok, "gap_law failed")
      if (allocated(error)) return
      call check(error, all(pa == pr) .and. all(da == dr), "no hysteresis")
      if (allocated(error)) return
      do k = 2, n
         p = pa(k)
         if (g(k) >= 1.0_wp) then
            call check(error, p == 0.0_wp .and. da(k) == 0.0_wp, "apart beyond gbar* = 1")
         else
            call check(error, abs(1.0_wp - p + p*log(p) - g(k)) <= 1.0e-13_wp, &
               "gbar* = 1 - P* + P* ln P*")
            if (allocated(error)) return
            call check(error, abs(da(k)*log(p) - 1.0_wp) <= 1.0e-7_wp, "dP*/dgbar* = 1/ln P*")
         end if
         if (allocated(error)) return
      end do
   end subroutine test_westergaard_law

   !> W* = int (P_approach - P_retract) dgbar* from the gap law on a fine grid (the
   !> trapezoid rule across the jumps: error ~h dP/2 per jump, 1.1e-3 here) against W*.
   subroutine test_law_energy(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      type(gap_path_type) :: path
      integer, parameter :: n = 4001
      real(wp) :: g(n), pa(n), pr(n), da(n), dr(n), w, h
      integer :: status, k
      call new_params(0.3_wp, 1.0_wp, params, status)
      call gap_path(model_dw, params, path, status)
      h = 1.3_wp/real(n - 1, wp)
      g = [(h*real(k - 1, wp), k = 1, n)]
      call gap_law(model_dw, params, g, pa, pr, da, dr, status)
      call check(error, status == wa_ok, "gap_law failed")
      if (allocated(error)) return
      w = h*(sum(pa - pr) - 0.5_wp*(pa(1) - pr(1) + pa(n) - pr(n)))
      call check_close(error, w, path%w_star, 5.0e-3_wp, what="W* from the gap law (DW)")
   end subroutine test_law_energy

   subroutine test_law_bad_input(error)
      type(error_type), allocatable, intent(out) :: error
      type(params_type) :: params
      real(wp) :: pa(2), pr(2), da(2), dr(2)
      integer :: status
      character(len=200) :: msg
      call new_params(0.3_wp, 1.0_wp, params, status)
      msg = ""
      call gap_law(model_dw, params, [0.5_wp, -0.1_wp], pa, pr, da, dr, status, msg)
      call check(error, status == wa_invalid_argument .and. index(msg, "gbar") > 0, &
         "negative gbar rejected")
   end subroutine test_law_bad_input

   !> Load control: the energy released by each jump that lands on the branch is finite
   !> and >= 0 (the potential E + P0 gbar* can only fall in a jump).
   subroutine test_load_jump_energies(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: cases(2, 4) = reshape([0.3_wp, 1.0_wp, 0.3_wp, 5.0_wp, &
         0.6_wp, 1.0_wp, 1.0_wp, 3.0_wp], [2, 4])
      integer, parameter :: models(2) = [model_dw, model_md]
      type(params_type) :: params
      type(branch_type) :: b
      type(path_type) :: lp
      real(wp) :: energy(64)
      integer :: status, k, m, i, n_jumps
      n_jumps = 0
      do m = 1, 2
         do k = 1, size(cases, 2)
            call new_params(cases(1, k), cases(2, k), params, status)
            call trace_branch(models(m), params, b, status)
            call path_from_branch(models(m), params, b, lp, status)
            call check(error, status == wa_ok, "load path")
            if (allocated(error)) return
            call load_jump_energies(models(m), params, b, lp, energy, status)
            call check(error, status == wa_ok, "load_jump_energies")
            if (allocated(error)) return
            do i = 1, lp%n - 1
               if (lp%event(i) /= event_jump_start .or. lp%a_star(i) <= 0.0_wp) cycle
               if (.not. (lp%event(i + 1) == event_jump_end .or. &
                  lp%event(i + 1) == event_full_contact_reached)) cycle
               call check(error, energy(i) >= -1.0e-13_wp .and. energy(i) < 10.0_wp, &
                  "jump energy finite and >= 0")
               if (allocated(error)) return
               n_jumps = n_jumps + 1
            end do
         end do
      end do
      call check(error, n_jumps >= 4, "the cases have jumps")
   end subroutine test_load_jump_energies

end module test_gappath
