!> Benchmark of the performance targets (doc/accuracy-performance.md). Prints figures; asserts nothing.
!>   cd study && fpm run --profile release wavyadhesion-benchmark
program benchmark
   use, intrinsic :: iso_fortran_env, only: int64, error_unit
   use wavyadhesion
   use wa_kinds, only: wp
   implicit none
   character(len=64) :: arg, only
   integer :: i_arg

   only = "all"

   do i_arg = 1, command_argument_count()
      call get_command_argument(i_arg, arg)
      select case (arg)
      case ("--help", "-h")
         write (*, '(a)') "usage: wavyadhesion-benchmark [--help | --version | SECTION...]", &
            "Times DW and MD points, branches, critical forces, gap control and the adhesion", &
            "map against the performance targets (single core, medians over repeats) and", &
            "prints the figures. SECTION (default all): point branch grid critical gap map gapmap."
         stop
      case ("--version")
         write (*, '(a)') "wavyadhesion-benchmark "//wa_version
         stop
      case ("point", "branch", "grid", "critical", "gap", "map", "gapmap")
         if (only == "all") only = ""
         only = trim(only)//" "//trim(arg)
      case default
         write (error_unit, '(a)') "wavyadhesion-benchmark: unknown argument '"//trim(arg)// &
            "' (try --help)"
         stop 2
      end select
   end do

   write (*, '(a)') "wavyadhesion "//wa_version//" benchmark (one core; medians over repeats)"
   write (*, '(a)') "performance target: DW point <= 2 us, MD point <= 20 us, DW branch <= 2 ms,"
   write (*, '(a)') "                 MD branch <= 20 ms, critical forces 3 alpha x 200 mu (DW) <= 1 s"
   write (*, '(a)') "target (issue 13): adhesion map 200 alpha, DW <= 2 s, MD <= 20 s"
   write (*, '(a)') "target (issue 11): gap path <= 2x load path; gap law 401 rows DW <= 5 ms, MD <= 30 ms"
   if (wanted("point")) then
      call bench_points(model_dw, 0.3_wp, 1.0_wp)
      call bench_points(model_dw, 0.3_wp, 1000.0_wp)
      call bench_points(model_dw, 1.0_wp, 0.1_wp)
      call bench_points(model_md, 0.3_wp, 1.0_wp)
      call bench_points(model_md, 0.3_wp, 1000.0_wp)
   end if
   if (wanted("branch")) then
      call bench_branch(model_dw, 0.3_wp, 1.0_wp)
      call bench_branch(model_dw, 0.3_wp, 5.0_wp)
      call bench_branch(model_dw, 0.6_wp, 3.0_wp)
      call bench_branch(model_md, 0.3_wp, 1.0_wp)
      call bench_branch(model_md, 0.3_wp, 5.0_wp)
   end if
   if (wanted("grid")) then
      call bench_branch_grid(model_dw)
      call bench_branch_grid(model_md)
   end if
   if (wanted("critical")) call bench_critical()
   if (wanted("gap")) then
      call bench_gap(model_dw, 0.3_wp, 1.0_wp)
      call bench_gap(model_dw, 0.3_wp, 5.0_wp)
      call bench_gap(model_dw, 1.0_wp, 1.0_wp)
      call bench_gap(model_md, 0.3_wp, 1.0_wp)
      call bench_gap(model_md, 0.3_wp, 5.0_wp)
      call bench_gap(model_md, 1.0_wp, 1.0_wp)
   end if
   if (wanted("map")) then
      call bench_map(model_dw)
      call bench_map(model_md)
   end if
   if (wanted("gapmap")) then
      call bench_map(model_dw, map_control_gap)
      call bench_map(model_dw, map_control_both)
      call bench_map(model_md, map_control_gap)
      call bench_map(model_md, map_control_both)
   end if

contains

   logical function wanted(section)
      character(len=*), intent(in) :: section
      wanted = only == "all" .or. index(" "//trim(only)//" ", " "//section//" ") > 0
   end function wanted

   !> The adhesion map: 200 log alpha in [0.01, 10], mu in [1e-3, 1e3] (issue 13 targets:
   !> DW <= 2 s, MD <= 20 s). One run: the map is deterministic. control (default load):
   !> map_control_gap, map_control_both time the gap-control boundaries (opt-in).
   subroutine bench_map(model, control)
      integer, intent(in) :: model
      integer, intent(in), optional :: control
      type(map_type) :: map
      real(wp) :: alpha(200), t0, t, c0, c1
      integer :: j, status, n_points, ctl
      character(len=*), parameter :: ctl_name(3) = [character(len=5) :: "load", "gap", "both"]
      ctl = map_control_load
      if (present(control)) ctl = control
      alpha = [(10.0_wp**(-2.0_wp + 3.0_wp*real(j - 1, wp)/199.0_wp), j = 1, 200)]
      t0 = seconds()
      call cpu_time(c0)
      call adhesion_map(model, alpha, 1.0e-3_wp, 1.0e3_wp, 60, map, status, control=ctl)
      call cpu_time(c1)
      t = seconds() - t0
      n_points = 0
      do j = 1, map%n_boundaries
         n_points = n_points + map%boundary(j)%n
      end do
      write (*, '(a,a,a,a,a,f8.3,a,f8.3,a,i0,a,i0,a,i0,a,i0)') "map ", name(model), &
         " control ", trim(ctl_name(ctl)), " 200 alpha (0.01..10) x mu 1e-3..1e3: ", t, " s wall, ", c1 - c0, " s CPU  (", &
         map%n_boundaries, " curves, ", n_points, " points, ", map%n_paths, &
         " load paths)  status ", status
   end subroutine bench_map

   real(wp) function cpu_seconds()
      call cpu_time(cpu_seconds)
   end function cpu_seconds

   real(wp) function seconds()
      integer(int64) :: count, rate
      call system_clock(count, rate)
      seconds = real(count, wp)/real(rate, wp)
   end function seconds

   !> Median over 5 repeats of the time per point on 2000 a* in (0, 1/2).
   subroutine bench_points(model, alpha, mu)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu
      integer, parameter :: n = 2000, repeats = 5
      type(params_type) :: params
      type(state_type) :: s
      real(wp) :: times(repeats), t0, checksum
      integer :: i, r, status, failures
      call new_params(alpha, mu, params, status)
      checksum = 0
      failures = 0
      do r = 1, repeats
         t0 = seconds()
         do i = 1, n
            if (model == model_dw) then
               call dw_equilibrium(params, 0.5_wp*i/(n + 1.0_wp), s, status)
            else
               call md_equilibrium(params, 0.5_wp*i/(n + 1.0_wp), s, status)
            end if
            if (status /= wa_ok) failures = failures + 1
            checksum = checksum + s%p_star
         end do
         times(r) = (seconds() - t0)/n
      end do
      write (*, '(a,a,a,f6.3,a,g10.3,a,f9.3,a,i0,a,es10.3,a)') "point  ", name(model), &
         " alpha ", alpha, " mu ", mu, ": ", 1.0e6_wp*median(times), " us/point  (failures ", &
         failures/repeats, ", checksum ", checksum, ")"
      call bench_gbar(model, params, median(times))
   end subroutine bench_points

   !> The share of the point cost spent on the mean gap gbar (filled by the solvers):
   !> gbar alone on the same 2000 states (DW: dw_mean_gap from the quantities the case
   !> builders pass it; MD: md_state_gbar), and the point cost without it.
   subroutine bench_gbar(model, params, with_gbar)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: with_gbar
      integer, parameter :: n = 2000, repeats = 5
      type(state_type) :: states(n)
      real(wp) :: times(repeats), t0, checksum, g, sa(n), sq(n), sd2(n), sc(n), sqc(n)
      integer :: i, r, status
      do i = 1, n
         call model_equilibrium(model, params, 0.5_wp*i/(n + 1.0_wp), states(i), status)
         ! what the DW case builders have at hand when they call dw_mean_gap
         sa(i) = sin(acos(-1.0_wp)*states(i)%a_star)
         sq(i) = sin(acos(-1.0_wp)*(0.5_wp - states(i)%a_star))
         sd2(i) = sin(acos(-1.0_wp)*states(i)%gap_width)*sin(acos(-1.0_wp)* &
            (states(i)%a_star + states(i)%c_star))
         sc(i) = sin(acos(-1.0_wp)*states(i)%c_star)
         sqc(i) = sin(acos(-1.0_wp)*(0.5_wp - states(i)%c_star))
      end do
      checksum = 0
      do r = 1, repeats
         t0 = seconds()
         do i = 1, n
            if (model == model_dw) then
               g = dw_mean_gap(params%sigma0, sa(i), sq(i), sc(i), sqc(i), sd2(i))
            else
               g = md_state_gbar(params, states(i))
            end if
            checksum = checksum + g
         end do
         times(r) = (seconds() - t0)/n
      end do
      write (*, '(a,f9.3,a,f9.3,a,f6.1,a,es10.3,a)') "       gbar alone: ", &
         1.0e6_wp*median(times), " us/point; point without gbar: ", &
         1.0e6_wp*(with_gbar - median(times)), " us (gbar adds ", &
         100.0_wp*median(times)/(with_gbar - median(times)), " %; checksum ", checksum, ")"
   end subroutine bench_gbar

   subroutine bench_branch(model, alpha, mu)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu
      integer, parameter :: repeats = 7
      type(params_type) :: params
      type(branch_type) :: b
      real(wp) :: times(repeats), t0
      integer :: r, status
      call new_params(alpha, mu, params, status)
      do r = 1, repeats
         t0 = seconds()
         call trace_branch(model, params, b, status)
         times(r) = seconds() - t0
      end do
      write (*, '(a,a,a,f6.3,a,g10.3,a,f9.3,a,i0,a,i0,a,i0,a)') "branch ", name(model), &
         " alpha ", alpha, " mu ", mu, ": ", 1.0e3_wp*median(times), " ms  (", b%n, &
         " points, ", count(b%event(1:b%n) == event_fold), " folds, status ", status, ")"
   end subroutine bench_branch

   !> The slowest trace over the 7 x 7 grid alpha in {0.01, 0.1, 0.3, 0.6, 1, 3, 10} x
   !> mu in {0.001 .. 1000} (the main range; best of 3 runs per case).
   subroutine bench_branch_grid(model)
      integer, intent(in) :: model
      real(wp), parameter :: alphas(7) = [0.01_wp, 0.1_wp, 0.3_wp, 0.6_wp, 1.0_wp, 3.0_wp, &
         10.0_wp], mus(7) = [0.001_wp, 0.01_wp, 0.1_wp, 1.0_wp, 10.0_wp, 100.0_wp, 1000.0_wp]
      type(params_type) :: params
      type(branch_type) :: b
      real(wp) :: t0, t, best, worst, worst_alpha, worst_mu
      integer :: i, j, r, status, n_fail
      worst = 0.0_wp; worst_alpha = 0.0_wp; worst_mu = 0.0_wp; n_fail = 0
      do i = 1, 7
         do j = 1, 7
            call new_params(alphas(i), mus(j), params, status)
            best = huge(1.0_wp)
            do r = 1, 3
               t0 = seconds()
               call trace_branch(model, params, b, status)
               t = seconds() - t0
               best = min(best, t)
            end do
            if (status /= wa_ok) n_fail = n_fail + 1
            if (best > worst) then
               worst = best; worst_alpha = alphas(i); worst_mu = mus(j)
            end if
         end do
      end do
      write (*, '(a,a,a,f8.3,a,g10.3,a,g10.3,a,i0)') "branch ", name(model), &
         " 7x7 grid (alpha 0.01..10, mu 0.001..1000): slowest ", 1.0e3_wp*worst, &
         " ms at alpha ", worst_alpha, " mu ", worst_mu, "; failures ", n_fail
   end subroutine bench_branch_grid

   !> Gap control (issue 11): a gap-controlled path against the load path of the same case
   !> (both include the trace), and a 401-row gap-law table (gbar* 0..1.5, trace included).
   !> Process CPU time, best of the repeats (robust on a shared machine).
   subroutine bench_gap(model, alpha, mu)
      integer, intent(in) :: model
      real(wp), intent(in) :: alpha, mu
      integer, parameter :: repeats = 15, rows = 401
      type(params_type) :: params
      type(path_type) :: lp
      type(gap_path_type) :: gp
      real(wp) :: t_load(repeats), t_gap(repeats), t_law(repeats), t0
      real(wp) :: g(rows), pa(rows), pr(rows), da(rows), dr(rows)
      integer :: r, k, s1, s2, s3
      call new_params(alpha, mu, params, s1)
      g = [(1.5_wp*real(k - 1, wp)/real(rows - 1, wp), k=1, rows)]
      do r = 1, repeats
         t0 = cpu_seconds()
         call load_path(model, params, lp, s1)
         t_load(r) = cpu_seconds() - t0
         t0 = cpu_seconds()
         call gap_path(model, params, gp, s2)
         t_gap(r) = cpu_seconds() - t0
         t0 = cpu_seconds()
         call gap_law(model, params, g, pa, pr, da, dr, s3)
         t_law(r) = cpu_seconds() - t0
      end do
      write (*, '(a,a,a,f6.3,a,g10.3,a,f8.3,a,f8.3,a,f5.2,a,f8.3,a,i0,1x,i0,1x,i0,a)') &
         "gap ", name(model), " alpha ", alpha, " mu ", mu, ": load path ", &
         1.0e3_wp*minval(t_load), " ms, gap path ", 1.0e3_wp*minval(t_gap), " ms (", &
         minval(t_gap)/minval(t_load), "x), gap law 401 rows ", 1.0e3_wp*minval(t_law), &
         " ms  (status ", s1, s2, s3, ")"
   end subroutine bench_gap

   subroutine bench_critical()
      real(wp), parameter :: alphas(3) = [0.3_wp, 0.6_wp, 1.0_wp]
      real(wp) :: mu(200), p_fc(200), p_pf(200), t0, t
      integer :: fc(200), pf(200), i, j, status
      mu = [(0.01_wp*(1000.0_wp)**(real(i - 1, wp)/199.0_wp), i=1, 200)]
      t0 = seconds()
      do j = 1, 3
         call critical_sweep(model_dw, alphas(j), mu, p_fc, p_pf, fc, pf, status)
      end do
      t = seconds() - t0
      write (*, '(a,f8.3,a,i0)') "critical DW 3 alpha x 200 mu (0.01..10, log): ", t, &
         " s  status ", status
   end subroutine bench_critical

   real(wp) function median(x)
      real(wp), intent(in) :: x(:)
      real(wp) :: y(size(x)), tmp
      integer :: i, j
      y = x
      do i = 2, size(y)
         tmp = y(i)
         j = i - 1
         do while (j >= 1)
            if (y(j) <= tmp) exit
            y(j + 1) = y(j)
            j = j - 1
         end do
         y(j + 1) = tmp
      end do
      median = y((size(y) + 1)/2)
   end function median

   function name(model)
      integer, intent(in) :: model
      character(len=2) :: name
      name = merge("dw", "md", model == model_dw)
   end function name

end program benchmark
