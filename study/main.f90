!> wavyadhesion-study: error against run time of the library's numerical choices, the
!> comparison with a straightforward scipy implementation, and the stiff/extreme grid
!> (doc/accuracy-performance.md: the accuracy and performance targets). Prints tables; writes the data of
!> the tables and plots into the output directory (default build/study).
!>
!>   cd study && fpm run --profile release wavyadhesion-study -- [command] [--quick] [--no-peer] [--out DIR]
!>   commands: all (default: dw md peer curve extreme), dw, md, peer, curve, extreme,
!>             samples (writes study/data/samples.txt for tools/reference/study_reference.py check)
!>   --quick: every 7th point of the work-precision sets; --no-peer: skip scipy.
!> critical_forces is load_path's P_fc*, P_pf*; the study calls load_path for its events.
!>
!> Run from the repository root (reads test/data/*.txt and study/data/*.txt, runs
!> python3 study/peer_scipy.py). Timings: one core, best of several passes over the
!> point set (the machine may be shared), per equilibrium point.
program wavyadhesion_study
   use, intrinsic :: iso_c_binding, only: c_funptr
   use wavyadhesion
   use wa_kinds, only: wp
   use wa_gsl, only: gsl_set_error_handler_off
   use wa_study_util, only: to_repository_root, seconds, median, spec_error, ref_table, read_table, point_set, &
      ref_states_of
   use wa_dw, only: dw_options, dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag
   use wa_md, only: md_options, md_prepare_options, md_psi_gauss, md_psi_qaws, md_psi_qag, &
      md_psi_qags
   implicit none

   !> One point of a work-precision set: inputs and the reference state.
   type :: wp_point
      real(wp) :: alpha, mu, a_star, c_ref, p_ref
      type(params_type) :: params
   end type wp_point

   !> One configuration of the work-precision study and its results.
   type :: wp_row
      character(len=40) :: label = ""
      character(len=12) :: method = ""
      real(wp) :: tol = 0, xtol = 0
      logical :: library_call = .false.
      real(wp) :: max_err = 0, med_err = 0, time_us = 0, mean_nres = 0
      integer :: n_over = 0, n_fail = 0
      !> (alpha, mu, a*) of the worst point
      real(wp) :: worst(3) = 0
   end type wp_row

   character(len=256) :: command, arg, out_dir
   logical :: quick, run_peer
   integer :: i
   type(c_funptr) :: old_handler

   old_handler = gsl_set_error_handler_off()
   command = "all"
   call to_repository_root()
   out_dir = "build/study"
   quick = .false.
   run_peer = .true.
   i = 1
   do while (i <= command_argument_count())
      call get_command_argument(i, arg)
      select case (trim(arg))
      case ("--quick"); quick = .true.
      case ("--no-peer"); run_peer = .false.
      case ("--out")
         i = i + 1
         call get_command_argument(i, out_dir)
      case ("-h", "--help")
         write (*, '(a)') "usage: wavyadhesion-study [all|dw|md|peer|curve|extreme|samples] "// &
            "[--quick] [--no-peer] [--out DIR]"
         stop
      case default
         command = arg
      end select
      i = i + 1
   end do
   call execute_command_line("mkdir -p "//trim(out_dir))
   write (*, '(a)') "wavyadhesion "//wa_version//" accuracy/performance study; output in "// &
      trim(out_dir)
   select case (trim(command))
   case ("all")
      call study_dw_wp()
      call study_md_wp()
      if (run_peer) call study_peer()
      if (run_peer) call study_curve()
      call study_extreme(.false.)
   case ("dw"); call study_dw_wp()
   case ("md"); call study_md_wp()
   case ("peer"); call study_peer()
   case ("curve"); call study_curve()
   case ("extreme"); call study_extreme(.false.)
   case ("samples"); call study_extreme(.true.)
   case default
      write (*, '(a)') "unknown command "//trim(command)
      stop 2
   end select

contains

   ! =============================================================== work-precision, DW

   !> The case-1 points of test/data/dw.txt (the main range, mpmath at 34 digits).
   subroutine dw_points(pts)
      type(wp_point), allocatable, intent(out) :: pts(:)
      type(ref_table) :: t
      integer :: i, n, st
      call read_table("test/data/dw.txt", t)
      allocate (pts(count(t%zone_case(1:t%n) == 1)))
      n = 0
      do i = 1, t%n
         if (t%zone_case(i) /= 1) cycle
         if (quick .and. mod(i, 7) /= 0) cycle
         n = n + 1
         pts(n) = wp_point(t%alpha(i), t%mu(i), t%a_star(i), t%c_star(i), t%p_star(i), &
            params_type())
         call new_params(t%alpha(i), t%mu(i), pts(n)%params, st)
      end do
      pts = pts(1:n)
   end subroutine dw_points

   subroutine study_dw_wp()
      type(wp_point), allocatable :: pts(:)
      type(wp_row), allocatable :: rows(:)
      type(dw_options) :: v
      real(wp), parameter :: xtols(7) = [1e-4_wp, 1e-6_wp, 1e-8_wp, 1e-10_wp, 1e-12_wp, &
         1e-14_wp, 1e-15_wp]
      real(wp), parameter :: qtols(6) = [1e-4_wp, 1e-6_wp, 1e-8_wp, 1e-10_wp, 1e-12_wp, 1e-15_wp]
      integer :: k
      call dw_points(pts)
      write (*, '(/,a,i0,a)') "== DW work-precision: ", size(pts), &
         " case-1 points of test/data/dw.txt (alpha 0.01..10, mu 1e-3..1e3, a* 1e-6..1/2-1e-9)"
      allocate (rows(0))
      rows = [rows, dw_row("library dw_equilibrium (default)", "agm", 0.0_wp, &
         4*epsilon(1.0_wp), .true., pts)]
      do k = 1, size(xtols)
         v = dw_options(xtol=xtols(k))
         rows = [rows, dw_row("AGM, Brent xtol", "agm", 0.0_wp, xtols(k), .false., pts, v)]
      end do
      v = dw_options()
      rows = [rows, dw_row("AGM (options at their defaults)", "agm", 0.0_wp, v%xtol, .false., &
         pts, v)]
      v = dw_options(istar_method=dw_istar_carlson)
      rows = [rows, dw_row("Carlson R_F,R_D,R_J (GSL)", "carlson", 0.0_wp, v%xtol, .false., pts, v)]
      do k = 1, size(qtols)
         v = dw_options(istar_method=dw_istar_tanh_sinh, istar_rtol=qtols(k))
         rows = [rows, dw_row("tanh-sinh quadrature, rtol", "tanh-sinh", qtols(k), v%xtol, &
            .false., pts, v)]
      end do
      do k = 1, size(qtols)
         v = dw_options(istar_method=dw_istar_qag, istar_rtol=max(qtols(k), 1.2e-14_wp))
         rows = [rows, dw_row("GSL QAG (GK21), epsrel", "qag", v%istar_rtol, v%xtol, .false., &
            pts, v)]
      end do
      call print_rows("dw", rows, size(pts))
   end subroutine study_dw_wp

   function dw_row(label, method, tol, xtol, library_call, pts, v) result(row)
      character(len=*), intent(in) :: label, method
      real(wp), intent(in) :: tol, xtol
      logical, intent(in) :: library_call
      type(wp_point), intent(in) :: pts(:)
      type(dw_options), intent(in), optional :: v
      type(wp_row) :: row
      row = measured_row(label, method, tol, xtol, library_call, pts, .true., dw=v)
   end function dw_row

   !> Accuracy on every point, then the best time per point over repeated passes.
   function measured_row(label, method, tol, xtol, library_call, pts, is_dw, dw, md) result(row)
      character(len=*), intent(in) :: label, method
      real(wp), intent(in) :: tol, xtol
      logical, intent(in) :: library_call
      type(wp_point), intent(in) :: pts(:)
      !> The model, and its solver variant (absent for the library's own call)
      logical, intent(in) :: is_dw
      type(dw_options), intent(in), optional :: dw
      type(md_options), intent(in), optional :: md
      type(wp_row) :: row
      real(wp) :: err(size(pts)), t0, best, total
      type(state_type) :: s
      integer :: i, st, nres, pass, nsum
      row%label = label; row%method = method; row%tol = tol; row%xtol = xtol
      row%library_call = library_call
      nsum = 0
      do i = 1, size(pts)                       ! accuracy pass (also warms up)
         call solve_point(pts(i), library_call, is_dw, s, st, nres, dw, md)
         nsum = nsum + nres
         err(i) = spec_error(s%c_star, s%p_star, pts(i)%c_ref, pts(i)%p_ref)
         if (st /= wa_ok .or. s%zone_case /= zone_inside) err(i) = huge(1.0_wp)
         if (err(i) == huge(1.0_wp)) row%n_fail = row%n_fail + 1
      end do
      row%mean_nres = real(nsum, wp)/size(pts)
      best = huge(1.0_wp)
      total = 0
      pass = 0
      do while (pass < 3 .or. (total < 0.5_wp .and. pass < 200))
         t0 = seconds()
         do i = 1, size(pts)
            call solve_point(pts(i), library_call, is_dw, s, st, nres, dw, md)
         end do
         t0 = seconds() - t0
         best = min(best, t0)
         total = total + t0
         pass = pass + 1
      end do
      row%time_us = 1e6_wp*best/size(pts)
      call summarize(err, row)
      i = maxloc(err, dim=1)
      row%worst = [pts(i)%alpha, pts(i)%mu, pts(i)%a_star]
   end function measured_row

   !> One equilibrium by the library's default call or with the options of a variant.
   subroutine solve_point(pt, library_call, is_dw, s, st, nres, dw, md)
      type(wp_point), intent(in) :: pt
      logical, intent(in) :: library_call, is_dw
      type(state_type), intent(out) :: s
      integer, intent(out) :: st, nres
      type(dw_options), intent(in), optional :: dw
      type(md_options), intent(in), optional :: md
      nres = 0
      if (library_call) then
         if (is_dw) then
            call dw_equilibrium(pt%params, pt%a_star, s, st)
         else
            call md_equilibrium(pt%params, pt%a_star, s, st)
         end if
      else if (is_dw) then
         call dw_equilibrium(pt%params, pt%a_star, s, st, options=dw, n_residuals=nres)
      else
         call md_equilibrium(pt%params, pt%a_star, s, st, options=md, n_residuals=nres)
      end if
   end subroutine solve_point

   subroutine summarize(err, row)
      real(wp), intent(in) :: err(:)
      type(wp_row), intent(inout) :: row
      row%max_err = maxval(err)
      row%med_err = median(err)
      row%n_over = count(err > 1e-12_wp)
   end subroutine summarize

   subroutine print_rows(model, rows, npts)
      character(len=*), intent(in) :: model
      type(wp_row), intent(in) :: rows(:)
      integer, intent(in) :: npts
      integer :: k, u
      character(len=:), allocatable :: path
      path = trim(out_dir)//"/wp_"//model//".txt"
      open (newunit=u, file=path, status="replace", action="write")
      write (u, '(a,i0,a)') "# work-precision, ", npts, " points; err = target error (max of "// &
         "rel c*, rel P* or abs P* where |P*|<1e-3) vs mpmath; time per point [us], best pass"
      write (u, '(a)') "# method tol xtol library_call max_err median_err n_over_1e-12 "// &
         "n_fail time_us mean_residuals label worst_alpha worst_mu worst_a_star"
      write (*, '(a)') "   configuration                        tol      xtol      max err  "// &
         "median err  >1e-12 fail  us/point  residuals"
      do k = 1, size(rows)
         associate (r => rows(k))
            write (*, '(3x,a36,2es9.1,2es11.2,i7,i5,f10.2,f10.1)') r%label, r%tol, r%xtol, &
               r%max_err, r%med_err, r%n_over, r%n_fail, r%time_us, r%mean_nres
            write (u, '(a,1x,es10.3,1x,es10.3,1x,l1,2(1x,es10.3),2(1x,i0),1x,es11.4,1x,f8.2,1x,a,3es25.17)') &
               trim(r%method), r%tol, r%xtol, r%library_call, r%max_err, r%med_err, r%n_over, &
               r%n_fail, r%time_us, r%mean_nres, '"'//trim(r%label)//'"', r%worst
         end associate
      end do
      write (*, '(a)') "   worst point of each configuration (alpha, mu, a*):"
      do k = 1, size(rows)
         write (*, '(3x,a36,es9.1,a,2es10.2,es23.15)') rows(k)%label, rows(k)%tol, " :", rows(k)%worst
      end do
      close (u)
   end subroutine print_rows

   ! =============================================================== work-precision, MD

   !> Points of test/data/md.txt with exactly one case-1 state (that state is then the
   !> principal one); points with two case-1 roots are left out (the set of the recorded
   !> study runs, whose MD solver variants did not look for hidden root pairs).
   subroutine md_points(pts)
      type(wp_point), allocatable, intent(out) :: pts(:)
      type(ref_table) :: t
      type(point_set) :: ps
      integer :: i, j, n, st, n1
      call read_table("test/data/md.txt", t)
      ps = ref_states_of(t)
      allocate (pts(ps%n))
      n = 0
      do i = 1, ps%n
         n1 = count(t%zone_case(ps%first(i):ps%last(i)) == 1)
         if (n1 /= 1) cycle
         if (quick .and. mod(i, 7) /= 0) cycle
         j = ps%first(i)
         n = n + 1
         pts(n) = wp_point(t%alpha(j), t%mu(j), t%a_star(j), t%c_star(j), t%p_star(j), &
            params_type())
         call new_params(t%alpha(j), t%mu(j), pts(n)%params, st)
      end do
      pts = pts(1:n)
   end subroutine md_points

   subroutine study_md_wp()
      type(wp_point), allocatable :: pts(:)
      type(wp_row), allocatable :: rows(:)
      type(md_options) :: v
      real(wp), parameter :: xtols(7) = [1e-4_wp, 1e-6_wp, 1e-8_wp, 1e-10_wp, 1e-12_wp, &
         1e-14_wp, 1e-15_wp]
      real(wp), parameter :: qtols(5) = [1e-6_wp, 1e-8_wp, 1e-10_wp, 1e-12_wp, 1.2e-14_wp]
      integer :: k, nodes, st
      call md_points(pts)
      write (*, '(/,a,i0,a)') "== MD work-precision: ", size(pts), " points of test/data/md.txt"// &
         " with one case-1 state (principal state; same grid as DW)"
      allocate (rows(0))
      rows = [rows, md_row("library md_equilibrium (default)", "lib-rules", 0.0_wp, &
         4*epsilon(1.0_wp), .true., pts)]
      do k = 1, size(xtols)
         v = md_options(xtol=xtols(k))
         rows = [rows, md_row("lib rules, Brent xtol", "lib-rules", 0.0_wp, xtols(k), .false., &
            pts, v)]
      end do
      v = md_options()
      rows = [rows, md_row("lib rules (options at their defaults)", "lib-rules", 0.0_wp, &
         v%xtol, .false., pts, v)]
      do nodes = 16, 64, 16
         if (nodes == 48) cycle
         v = md_options(psi_method=md_psi_gauss, psi_nodes=nodes)
         call md_prepare_options(v, st)              ! the rules, once
         rows = [rows, md_row("Gauss-log + Gauss-Legendre, nodes", "gauss", real(nodes, wp), &
            v%xtol, .false., pts, v)]
      end do
      do k = 1, size(qtols)
         v = md_options(psi_method=md_psi_qaws, psi_rtol=qtols(k))
         rows = [rows, md_row("GSL QAWS + QAG, epsrel", "qaws", qtols(k), v%xtol, .false., pts, v)]
      end do
      do k = 1, size(qtols)
         if (qtols(k) == 1e-12_wp) cycle
         v = md_options(psi_method=md_psi_qag, psi_rtol=qtols(k))
         rows = [rows, md_row("GSL QAG (GK21), epsrel", "qag", qtols(k), v%xtol, .false., pts, v)]
      end do
      do k = 1, size(qtols)
         if (qtols(k) == 1e-12_wp) cycle
         v = md_options(psi_method=md_psi_qags, psi_rtol=qtols(k))
         rows = [rows, md_row("GSL QAGS, epsrel", "qags", qtols(k), v%xtol, .false., pts, v)]
      end do
      call print_rows("md", rows, size(pts))
   end subroutine study_md_wp

   function md_row(label, method, tol, xtol, library_call, pts, v) result(row)
      character(len=*), intent(in) :: label, method
      real(wp), intent(in) :: tol, xtol
      logical, intent(in) :: library_call
      type(wp_point), intent(in) :: pts(:)
      type(md_options), intent(in), optional :: v
      type(wp_row) :: row
      row = measured_row(label, method, tol, xtol, library_call, pts, .false., md=v)
   end function md_row

   ! =============================================================== the scipy peer

   !> Same DW points as the work-precision study, solved by the library and by
   !> study/peer_scipy.py (scipy quad + brentq on (2.25b) in C) in the same run.
   subroutine study_peer()
      type(wp_point), allocatable :: pts(:)
      real(wp), allocatable :: t_lib(:), e_lib(:)
      character(len=:), allocatable :: list
      integer :: u, i
      call dw_points(pts)
      write (*, '(/,a,i0,a)') "== DW versus a straightforward scipy implementation "// &
         "(study/peer_scipy.py), ", size(pts), " case-1 points of test/data/dw.txt"
      list = trim(out_dir)//"/peer_points.txt"
      open (newunit=u, file=list, status="replace", action="write")
      write (u, '(a)') "# alpha mu a_star"
      do i = 1, size(pts)
         write (u, '(3es25.17)') pts(i)%alpha, pts(i)%mu, pts(i)%a_star
      end do
      close (u)
      allocate (t_lib(size(pts)), e_lib(size(pts)))
      call time_lib_points(pts, t_lib, e_lib)
      write (*, '(a)') "   implementation                  max err   median err  >1e-12  "// &
         "fail   mean us/pt  median us/pt  ratio(mean)  ratio(median)"
      write (*, '(3x,a30,2es11.2,i8,i6,2f13.2,2a13)') "wavyadhesion dw_equilibrium", &
         maxval(e_lib), median(e_lib), count(e_lib > 1e-12_wp), count(e_lib == huge(1.0_wp)), &
         1e6_wp*sum(t_lib)/size(pts), 1e6_wp*median(t_lib), "1", "1"
      open (newunit=u, file=trim(out_dir)//"/peer_summary.txt", status="replace", action="write")
      write (u, '(a)') "# name max_err median_err n_over_1e-12 n_fail mean_us median_us "// &
         "ratio_of_means median_ratio"
      write (u, '(a,2es11.3,2i6,2f12.3,2f10.1)') "library", maxval(e_lib), median(e_lib), &
         count(e_lib > 1e-12_wp), count(e_lib == huge(1.0_wp)), 1e6_wp*sum(t_lib)/size(pts), &
         1e6_wp*median(t_lib), 1.0_wp, 1.0_wp
      call peer_row("default", pts, t_lib, u)
      call peer_row("tight", pts, t_lib, u)
      close (u)
   end subroutine study_peer

   !> Per-point time of dw_equilibrium (best of 5 runs of 200 calls) and its error.
   subroutine time_lib_points(pts, t, e)
      type(wp_point), intent(in) :: pts(:)
      real(wp), intent(out) :: t(:), e(:)
      type(state_type) :: s
      integer :: i, r, k, st
      real(wp) :: t0
      do i = 1, size(pts)
         call dw_equilibrium(pts(i)%params, pts(i)%a_star, s, st)
         e(i) = spec_error(s%c_star, s%p_star, pts(i)%c_ref, pts(i)%p_ref)
         if (st /= wa_ok) e(i) = huge(1.0_wp)
         t(i) = huge(1.0_wp)
         do r = 1, 5
            t0 = seconds()
            do k = 1, 200
               call dw_equilibrium(pts(i)%params, pts(i)%a_star, s, st)
            end do
            t(i) = min(t(i), (seconds() - t0)/200)
         end do
      end do
   end subroutine time_lib_points

   !> Run the peer with one configuration, read its results, print its row.
   subroutine peer_row(config, pts, t_lib, us)
      character(len=*), intent(in) :: config
      type(wp_point), intent(in) :: pts(:)
      real(wp), intent(in) :: t_lib(:)
      integer, intent(in) :: us
      character(len=:), allocatable :: res, cmd
      real(wp) :: e(size(pts)), t(size(pts)), ratio(size(pts)), v(6)
      integer :: u, ios, n, stat, zc, pst
      character(len=512) :: line
      res = trim(out_dir)//"/peer_"//config//".txt"
      cmd = "python3 study/peer_scipy.py points "//trim(out_dir)//"/peer_points.txt "//res// &
         " --config "//config
      call execute_command_line(cmd, exitstat=stat)
      if (stat /= 0) then
         write (*, '(a)') "   (peer not run: "//cmd//" failed; pip install scipy)"
         return
      end if
      open (newunit=u, file=res, status="old", action="read")
      n = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#") cycle
         ! alpha mu a_star c_star P_star zone_case status seconds
         read (line, *) v(1:5), zc, pst, v(6)
         n = n + 1
         e(n) = spec_error(v(4), v(5), pts(n)%c_ref, pts(n)%p_ref)
         if (pst /= 0 .or. zc /= 1) e(n) = huge(1.0_wp)
         t(n) = v(6)
      end do
      close (u)
      ratio = t/t_lib
      write (*, '(3x,a30,2es11.2,i8,i6,2f13.1,2f13.0)') "scipy peer, "//config, maxval(e), &
         median(e), count(e > 1e-12_wp), count(e == huge(1.0_wp)), 1e6_wp*sum(t)/n, &
         1e6_wp*median(t), sum(t)/sum(t_lib), median(ratio)
      write (*, '(3x,a,i0,a,f8.0,a,f8.0)') "   per-point speed ratio over the ", n, &
         " points: min ", minval(ratio), ", max ", maxval(ratio)
      write (us, '(a,2es11.3,2i6,2f12.3,2f10.1)') "scipy-"//config, maxval(e), median(e), &
         count(e > 1e-12_wp), count(e == huge(1.0_wp)), 1e6_wp*sum(t)/n, 1e6_wp*median(t), &
         sum(t)/sum(t_lib), median(ratio)
   end subroutine peer_row

   ! =============================================================== a traced curve

   !> 400 points of one DW curve: the library (trace_branch; 400 dw_equilibrium calls on
   !> a* = 0.5 i/401) against the peer's 400 brentq solves on the same a*; errors at every
   !> 10th point against study/data/samples_check.txt (tag "curve", mpmath 50 digits).
   subroutine study_curve()
      real(wp), parameter :: cases(2, 2) = reshape([0.3_wp, 1.0_wp, 0.3_wp, 5.0_wp], [2, 2])
      integer :: k
      write (*, '(/,a)') "== One DW curve of 400 points: library vs scipy peer"
      write (*, '(a)') "   alpha   mu   implementation                          time [ms]   "// &
         "max err (40 pts)  points   ratio"
      do k = 1, 2
         call curve_case(cases(1, k), cases(2, k))
      end do
   end subroutine study_curve

   subroutine curve_case(alpha, mu)
      real(wp), intent(in) :: alpha, mu
      integer, parameter :: n = 400
      type(params_type) :: params
      type(branch_type) :: b
      type(state_type) :: s(n)
      real(wp) :: a(n), t_eq, t_tr, t0, c_ref(n), p_ref(n), e_lib, e_peer, t_peer, v(6), err
      logical :: have(n)
      integer :: i, st, pass, u, ios, zc, pst, stat, nb
      character(len=512) :: line
      character(len=:), allocatable :: list, res, cmd
      character(len=8) :: config
      call new_params(alpha, mu, params, st)
      a = [(0.5_wp*i/401.0_wp, i=1, n)]
      call curve_reference(alpha, mu, a, c_ref, p_ref, have)
      t_eq = huge(1.0_wp); t_tr = huge(1.0_wp)
      do pass = 1, 7
         t0 = seconds()
         do i = 1, n
            call dw_equilibrium(params, a(i), s(i), st)
         end do
         t_eq = min(t_eq, seconds() - t0)
         t0 = seconds()
         call trace_branch(model_dw, params, b, st)
         t_tr = min(t_tr, seconds() - t0)
      end do
      nb = b%n
      e_lib = 0
      do i = 1, n
         if (have(i)) e_lib = max(e_lib, spec_error(s(i)%c_star, s(i)%p_star, c_ref(i), p_ref(i)))
      end do
      write (*, '(2f6.2,3x,a36,f12.3,es16.2,i9)') alpha, mu, "dw_equilibrium x 400", 1e3_wp*t_eq, &
         e_lib, n
      write (*, '(2f6.2,3x,a36,f12.3,a16,i9)') alpha, mu, "trace_branch (all folds located)", &
         1e3_wp*t_tr, "(extreme grid)", nb
      list = trim(out_dir)//"/curve_points.txt"
      open (newunit=u, file=list, status="replace", action="write")
      do i = 1, n
         write (u, '(3es25.17)') alpha, mu, a(i)
      end do
      close (u)
      do pst = 1, 2
         config = merge("default", "tight  ", pst == 1)
         res = trim(out_dir)//"/curve_peer_"//trim(config)//".txt"
         cmd = "python3 study/peer_scipy.py points "//list//" "//res//" --config "//trim(config)
         call execute_command_line(cmd, exitstat=stat)
         if (stat /= 0) cycle
         open (newunit=u, file=res, status="old", action="read")
         i = 0; e_peer = 0; t_peer = 0
         do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == "#") cycle
            read (line, *) v(1:5), zc, st, v(6)
            i = i + 1
            t_peer = t_peer + v(6)
            if (have(i)) then
               err = spec_error(v(4), v(5), c_ref(i), p_ref(i))
               if (st /= 0) err = huge(1.0_wp)
               e_peer = max(e_peer, err)
            end if
         end do
         close (u)
         write (*, '(2f6.2,3x,a36,f12.1,es16.2,i9,f8.0,a)') alpha, mu, &
            "scipy peer "//trim(config)//", 400 brentq", 1e3_wp*t_peer, e_peer, i, &
            t_peer/t_eq, "x (vs 400 dw_equilibrium)"
         write (*, '(41x,a,f10.0,a)') "ratio vs trace_branch:", t_peer/t_tr, "x"
      end do
   end subroutine curve_case

   !> mpmath states at the a* of the curve (study/data/samples_check.txt, tag "curve").
   subroutine curve_reference(alpha, mu, a, c_ref, p_ref, have)
      real(wp), intent(in) :: alpha, mu, a(:)
      real(wp), intent(out) :: c_ref(:), p_ref(:)
      logical, intent(out) :: have(:)
      character(len=1024) :: line
      character(len=32) :: tag, kind, model
      real(wp) :: v(9)
      integer :: u, ios, i
      have = .false.
      c_ref = 0; p_ref = 0
      open (newunit=u, file="study/data/samples_check.txt", status="old", action="read", &
         iostat=ios)
      if (ios /= 0) then
         write (*, '(a)') "   (no study/data/samples_check.txt: run tools/reference/study_reference.py check)"
         return
      end if
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (line(1:1) == "#") cycle
         ! tag kind model alpha mu a_star c_lib p_lib a_ref c_ref p_ref ...
         read (line, *, iostat=ios) tag, kind, model, v
         if (ios /= 0 .or. tag /= "curve") cycle
         if (v(1) /= alpha .or. v(2) /= mu) cycle
         do i = 1, size(a)
            if (a(i) == v(3)) then
               have(i) = .true.
               c_ref(i) = v(7)
               p_ref(i) = v(8)
            end if
         end do
      end do
      close (u)
   end subroutine curve_reference

   ! =============================================================== stiff and extreme grid

   !> Pointwise (dw_roots, md_roots, principal calls) against study/data/extreme_*.txt
   !> (mpmath 50 digits), then trace_branch and critical_forces for each (alpha, mu).
   !> With write_samples, also writes study/data/samples.txt: branch points, folds, case
   !> switches and the points that define P_fc and P_pf, for tools/reference/study_reference.py.
   subroutine study_extreme(write_samples)
      logical, intent(in) :: write_samples
      integer :: u
      u = -1
      if (write_samples) then
         open (newunit=u, file="study/data/samples.txt", status="replace", action="write")
         write (u, '(a)') "# written by wavyadhesion-study samples; columns: tag kind model "// &
            "alpha mu a_star c_lib p_lib"
         call write_curve_samples(u)
      else
         call extreme_points(model_dw, "study/data/extreme_dw.txt")
         call extreme_points(model_md, "study/data/extreme_md.txt")
      end if
      call extreme_branches(model_dw, u)
      call extreme_branches(model_md, u)
      if (u /= -1) close (u)
   end subroutine study_extreme

   !> Every 10th a* of the two 400-point curves (with the library's values).
   subroutine write_curve_samples(u)
      integer, intent(in) :: u
      real(wp), parameter :: cases(2, 2) = reshape([0.3_wp, 1.0_wp, 0.3_wp, 5.0_wp], [2, 2])
      type(params_type) :: params
      type(state_type) :: s
      integer :: k, i, st
      real(wp) :: a
      do k = 1, 2
         call new_params(cases(1, k), cases(2, k), params, st)
         do i = 10, 400, 10
            a = 0.5_wp*i/401.0_wp
            call dw_equilibrium(params, a, s, st)
            write (u, '(a,3es25.17,2es25.17)') "curve pt dw ", cases(1, k), cases(2, k), a, &
               s%c_star, s%p_star
         end do
      end do
   end subroutine write_curve_samples

   subroutine extreme_points(model, path)
      integer, intent(in) :: model
      character(len=*), intent(in) :: path
      type(ref_table) :: t
      type(point_set) :: ps
      type(params_type) :: params
      type(state_type) :: roots(9), s
      integer :: i, j, st, st1, n, nref, nres, u, ios, jr, r
      real(wp) :: err, errp, t_call, t0, worst(7, 7)
      real(wp), parameter :: alphas(7) = [1e-4_wp, 1e-3_wp, 0.01_wp, 0.3_wp, 1.0_wp, 3.0_wp, 10.0_wp]
      real(wp), parameter :: mus(7) = [1e-4_wp, 1e-3_wp, 0.1_wp, 1.0_wp, 10.0_wp, 1e3_wp, 1e6_wp]
      character(len=200) :: verdict
      character(len=2) :: mname
      logical :: bad
      integer :: n_bad
      mname = merge("dw", "md", model == model_dw)
      open (newunit=u, file=path, status="old", action="read", iostat=ios)
      if (ios /= 0) then
         write (*, '(a)') "   (missing "//path//": python3 tools/reference/study_reference.py grid)"
         return
      end if
      close (u)
      call read_table(path, t)
      ps = ref_states_of(t)
      write (*, '(/,a,i0,a)') "== Extreme grid, "//mname//" pointwise: ", ps%n, &
         " points (alpha x mu x a*) against mpmath at 50 digits ("//path//")"
      open (newunit=u, file=trim(out_dir)//"/extreme_"//mname//".txt", status="replace", &
         action="write")
      write (u, '(a)') "# alpha mu a_star status_roots n_roots n_ref max_err_roots "// &
         "status_principal err_principal residuals us_per_roots_call verdict"
      worst = 0
      n_bad = 0
      write (*, '(a)') "   points that fail or exceed 1e-12 (main range marked *):"
      do i = 1, ps%n
         call new_params(ps%alpha(i), ps%mu(i), params, st)
         nref = count(t%zone_case(ps%first(i):ps%last(i)) /= 0)
         if (model == model_dw) then
            call dw_roots(params, ps%a_star(i), roots, n, st)
            call dw_equilibrium(params, ps%a_star(i), s, st1, n_residuals=nres)
         else
            call md_roots(params, ps%a_star(i), roots, n, st)
            call md_equilibrium(params, ps%a_star(i), s, st1, n_residuals=nres)
         end if
         t_call = huge(1.0_wp)
         do r = 1, 3
            t0 = seconds()
            do j = 1, 20
               if (model == model_dw) then
                  call dw_roots(params, ps%a_star(i), roots, n, st)
               else
                  call md_roots(params, ps%a_star(i), roots, n, st)
               end if
            end do
            t_call = min(t_call, (seconds() - t0)/20)
         end do
         ! every state against the reference (same order: case 1 by c*, then case 2)
         err = 0
         bad = .false.
         verdict = "ok"
         if (st /= wa_ok) then
            if (nref == 0 .and. st == wa_no_solution) then
               verdict = "ok (no state; status no_solution)"
            else
               verdict = "FAIL roots status "//status_message(st)
               bad = .true.
            end if
         else if (n /= nref) then
            write (verdict, '(a,i0,a,i0)') "FAIL roots: ", n, " states, reference ", nref
            bad = .true.
         else
            do j = 1, n
               jr = ps%first(i) + j - 1
               err = max(err, spec_error(roots(j)%c_star, roots(j)%p_star, t%c_star(jr), &
                  t%p_star(jr)))
               if (roots(j)%zone_case /= t%zone_case(jr)) then
                  verdict = "FAIL roots: zone case differs"
                  bad = .true.
               end if
            end do
         end if
         errp = 0
         if (st1 == wa_ok .and. nref > 0) then
            jr = ps%first(i)
            errp = spec_error(s%c_star, s%p_star, t%c_star(jr), t%p_star(jr))
            if (s%zone_case /= t%zone_case(jr)) then
               verdict = trim(verdict)//"; FAIL principal zone case"
               bad = .true.
            end if
         else if (st1 /= wa_ok .and. nref > 0) then
            verdict = trim(verdict)//"; FAIL principal status "//status_message(st1)
            bad = .true.
         end if
         err = max(err, errp)
         if (err == huge(1.0_wp)) bad = .true.
         if (.not. bad .and. err > 1e-12_wp) verdict = trim(verdict)//"; err > 1e-12"
         do j = 1, 7
            do r = 1, 7
               if (ps%alpha(i) == alphas(j) .and. ps%mu(i) == mus(r)) then
                  worst(j, r) = max(worst(j, r), err)
                  if (bad) worst(j, r) = huge(1.0_wp)
               end if
            end do
         end do
         write (u, '(3es25.17,i3,2i3,es11.3,i3,es11.3,i6,f11.3,1x,a)') ps%alpha(i), ps%mu(i), &
            ps%a_star(i), st, n, nref, err, st1, errp, nres, 1e6_wp*t_call, trim(verdict)
         if (bad .or. err > 1e-12_wp) then
            n_bad = n_bad + 1
            write (*, '(4x,a1,a,es9.2,a,es9.2,a,es24.17,a,es10.3,a,i0,a,a)') &
               merge("*", " ", in_main_range(ps%alpha(i), ps%mu(i), ps%a_star(i))), &
               " alpha=", ps%alpha(i), " mu=", ps%mu(i), " a*=", ps%a_star(i), " err=", err, &
               " residuals=", nres, " ", trim(verdict)
         end if
      end do
      close (u)
      write (*, '(a,i0,a)') "   (", n_bad, " listed)"
      write (*, '(a)') "   max error over a* (all states of *_roots and the principal state); "// &
         "FAIL = status/count/case wrong"
      write (*, '(a12,7es10.1)') "alpha \ mu", mus
      do j = 1, 7
         write (*, '(es12.1)', advance="no") alphas(j)
         do r = 1, 7
            if (worst(j, r) == huge(1.0_wp)) then
               write (*, '(a10)', advance="no") "FAIL"
            else
               write (*, '(es10.1)', advance="no") worst(j, r)
            end if
         end do
         write (*, *)
      end do
   end subroutine extreme_points

   pure logical function in_main_range(alpha, mu, a)
      real(wp), intent(in) :: alpha, mu, a
      in_main_range = alpha >= 0.01_wp .and. alpha <= 10.0_wp .and. mu >= 1e-3_wp .and. &
         mu <= 1e3_wp .and. a >= 1e-6_wp .and. a <= 0.5_wp - 1e-9_wp
   end function in_main_range

   !> trace_branch and critical_forces for each (alpha, mu) of the grid.
   subroutine extreme_branches(model, u)
      integer, intent(in) :: model, u
      real(wp), parameter :: alphas(7) = [1e-4_wp, 1e-3_wp, 0.01_wp, 0.3_wp, 1.0_wp, 3.0_wp, 10.0_wp]
      real(wp), parameter :: mus(7) = [1e-4_wp, 1e-3_wp, 0.1_wp, 1.0_wp, 10.0_wp, 1e3_wp, 1e6_wp]
      type(params_type) :: params
      type(branch_type) :: b
      type(path_type) :: path
      integer :: ia, im, st, st2, nf, ns, r, uo
      real(wp) :: t_tr, t_cf, t0, pfc, ppf
      logical :: nan_found
      character(len=2) :: mname
      character(len=256) :: msg
      mname = merge("dw", "md", model == model_dw)
      if (u == -1) then
         write (*, '(/,a)') "== Extreme grid, "//mname//": trace_branch and critical_forces"
         write (*, '(a)') "      alpha        mu  trace status  points folds switches  ms/trace"// &
            "   critical status          P_fc          P_pf  ms/call"
         open (newunit=uo, file=trim(out_dir)//"/branches_"//mname//".txt", status="replace", &
            action="write")
         write (uo, '(a)') "# alpha mu status_trace n_points n_folds n_switches ms_trace "// &
            "status_critical P_fc P_pf ms_critical nan"
      end if
      do ia = 1, size(alphas)
         do im = 1, size(mus)
            call new_params(alphas(ia), mus(im), params, st)
            msg = ""
            t_tr = huge(1.0_wp); t_cf = huge(1.0_wp)
            do r = 1, merge(1, 3, u /= -1)
               t0 = seconds()
               call trace_branch(model, params, b, st, msg)
               t_tr = min(t_tr, seconds() - t0)
               t0 = seconds()
               call load_path(model, params, path, st2)
               t_cf = min(t_cf, seconds() - t0)
            end do
            pfc = path%p_fc; ppf = path%p_pf
            nf = 0; ns = 0; nan_found = .false.
            if (b%n > 0) then
               nf = count(b%event(1:b%n) == event_fold)
               ns = count(b%event(1:b%n) == event_switch)
               nan_found = any(b%p_star(1:b%n) /= b%p_star(1:b%n)) .or. &
                  any(b%c_star(1:b%n) /= b%c_star(1:b%n)) .or. any(b%a_star(1:b%n) /= b%a_star(1:b%n))
            end if
            if (u == -1) then
               write (*, '(2es10.1,i7,1x,a9,i7,i6,i9,f10.3,i10,1x,a9,2es14.6,f9.3,a)') alphas(ia), &
                  mus(im), st, status_word(st), b%n, nf, ns, 1e3_wp*t_tr, st2, status_word(st2), &
                  pfc, ppf, 1e3_wp*t_cf, merge(" NaN!", "     ", nan_found)
               if (st /= wa_ok) write (*, '(25x,a)') "trace_branch: "//trim(msg)
               if (st == wa_ok .and. b%n > 0) then
                  if (b%a_star(b%n) /= 0.5_wp) write (*, '(25x,a,es24.16,a,es24.16,a)') &
                     "FAIL: status ok but the branch ends at a* =", b%a_star(b%n), &
                     " (c* =", b%c_star(b%n), "), not at a* = 1/2"
               end if
               write (uo, '(2es12.4,i3,3i7,f10.3,i3,2es25.17,f10.3,1x,l1)') alphas(ia), mus(im), &
                  st, b%n, nf, ns, 1e3_wp*t_tr, st2, pfc, ppf, 1e3_wp*t_cf, nan_found
            else if (st == wa_ok .and. st2 == wa_ok) then
               call write_branch_samples(u, mname, params, b, path)
            end if
         end do
      end do
      if (u == -1) close (uo)
   end subroutine extreme_branches

   function status_word(st) result(w)
      integer, intent(in) :: st
      character(len=9) :: w
      select case (st)
      case (wa_ok); w = "ok"
      case (wa_invalid_argument); w = "invalid"
      case (wa_no_solution); w = "no_sol"
      case (wa_not_converged); w = "not_conv"
      case (wa_capacity_too_small); w = "capacity"
      case (wa_numerical_error); w = "num_error"
      case default; w = "?"
      end select
   end function status_word

   !> Branch samples for the mpmath check: 5 points evenly spaced by index, every fold
   !> and case switch, and the points that define P_fc and P_pf (kind fc:* / pf:*).
   subroutine write_branch_samples(u, mname, params, b, path)
      integer, intent(in) :: u
      character(len=*), intent(in) :: mname
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: b
      type(path_type), intent(in) :: path
      integer :: k, j
      do j = 0, 4
         k = 1 + (j*(b%n - 1))/4
         call put_sample(u, "branch", "pt", mname, params, b, k)
      end do
      do k = 1, b%n
         if (b%event(k) == event_fold) call put_sample(u, "branch", "fold", mname, params, b, k)
         if (b%event(k) == event_switch) call put_sample(u, "branch", "switch", mname, params, b, k)
      end do
      ! P_fc: the branch point whose load it is (a maximum, or the end), or 0 (snap)
      k = find_point(b, path%p_fc, path%fc_mechanism == mechanism_gradual)
      if (k > 0) then
         call put_sample(u, "crit", "fc:"//point_kind(b, k), mname, params, b, k)
      else
         write (u, '(a,1x,a,1x,a,5es25.17)') "crit", "fc:snap", mname, params%alpha, &
            params%mu, 0.5_wp, 0.5_wp, path%p_fc
      end if
      ! P_pf: a minimum of the branch (jump out), or the gradual limit a* -> 0, which the
      ! library evaluates off the branch (its pull-off event holds a*, c*)
      k = find_point(b, path%p_pf, path%pf_mechanism == mechanism_gradual)
      if (k > 0) then
         call put_sample(u, "crit", "pf:"//point_kind(b, k), mname, params, b, k)
      else
         j = findloc(path%event(1:path%n), event_pull_off, dim=1)
         write (u, '(a,1x,a,1x,a,5es25.17)') "crit", merge("pf:limit   ", "pf:notfound", &
            path%pf_mechanism == mechanism_gradual .and. j > 0), mname, params%alpha, &
            params%mu, path%a_star(max(j, 1)), path%c_star(max(j, 1)), path%p_pf
      end if
   end subroutine write_branch_samples

   subroutine put_sample(u, tag, kind, mname, params, b, k)
      integer, intent(in) :: u, k
      character(len=*), intent(in) :: tag, kind, mname
      type(params_type), intent(in) :: params
      type(branch_type), intent(in) :: b
      write (u, '(a,1x,a,1x,a,5es25.17)') tag, kind, mname, params%alpha, params%mu, &
         b%a_star(k), b%c_star(k), b%p_star(k)
   end subroutine put_sample

   !> Index of the branch point carrying load p: an extremum (jump) or an end (gradual).
   integer function find_point(b, p, gradual) result(k)
      type(branch_type), intent(in) :: b
      real(wp), intent(in) :: p
      logical, intent(in) :: gradual
      integer :: i
      k = 0
      if (gradual) then
         if (b%p_star(b%n) == p) k = b%n
         if (b%p_star(1) == p) k = 1
         return
      end if
      do i = 1, b%n
         if (b%extremum(i) /= 0 .and. b%p_star(i) == p) then
            k = i
            return
         end if
      end do
   end function find_point

   function point_kind(b, k) result(kind)
      type(branch_type), intent(in) :: b
      integer, intent(in) :: k
      character(len=:), allocatable :: kind
      if (b%event(k) == event_fold) then
         kind = "fold"
      else if (b%event(k) == event_switch) then
         kind = "switch"
      else if (k == 1) then
         kind = "start"
      else if (k == b%n) then
         kind = "end"
      else
         kind = "other"
      end if
   end function point_kind

end program wavyadhesion_study
