!> The CLI's smooth-adhesion drivers (`--model lj`, the self-consistent Lennard-Jones 3-9
!> model): `branch` (the traced curve), `path` (load or gap control), `critical` (P_fc, P_pf
!> or W* with their N vs N/2 error estimates) and `profile` (gap and traction of one
!> traced state). The grid is --n (default automatic), the profile the sinusoid or the
!> samples of one period in --profile-file (read here: the library reads no files).
module wa_cli_lj
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
   use wa_kinds, only: wp
   use wa_text, only: int_text
   use wavyadhesion, only: params_type, new_params, lj_problem_type, lj_problem, lj_branch_type, &
      lj_trace, lj_cycle_type, lj_cycle, lj_paths, lj_path_type, status_message, wa_ok, &
      wa_invalid_argument, wa_capacity_too_small, lj_state_type, lj_state_at_a
   use wa_cli_options, only: cli_options, given, option_message
   use wa_cli_table, only: table_type, add_value, write_header, write_row, format_real
   use wa_cli_progress, only: progress_type, progress_start, progress_step, progress_end
   use wa_cli_common, only: usage_error, numerical_error, single
   implicit none
   private

   public :: run_lj_branch, run_lj_path, run_lj_critical, run_lj_profile

   !> Most samples a --profile-file may hold
   integer, parameter :: max_samples = 1000000

contains

   !> The grid (--n; 0 = automatic) and the profile samples (--profile-file; not
   !> allocated: the sinusoid) of the options.
   subroutine lj_inputs(tab, opts, n, samples)
      type(table_type), intent(inout) :: tab
      type(cli_options), intent(in) :: opts
      integer, intent(out) :: n
      real(wp), allocatable, intent(out) :: samples(:)
      n = 0
      if (given(opts, "--n")) n = opts%n_points
      if (allocated(opts%profile_file)) call read_samples(tab, opts%profile_file, samples)
   end subroutine lj_inputs

   !> --profile-file F: one height per line (over Delta), the undeformed gap profile at
   !> x_j = j/M, j = 0..M-1 (one period, the end point not repeated); blank lines and
   !> lines starting with # are skipped. A file that cannot be read or holds a line that
   !> is not a finite number is a usage error.
   subroutine read_samples(tab, path, samples)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: path
      real(wp), allocatable, intent(out) :: samples(:)
      real(wp), allocatable :: grown(:)
      character(len=512) :: line
      integer :: unit, ios, m, lineno
      real(wp) :: y
      open (newunit=unit, file=path, status="old", action="read", iostat=ios)
      if (ios /= 0) call usage_error(tab, "--profile-file: cannot open '"//path//"'")
      allocate (samples(1024))
      m = 0
      lineno = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         lineno = lineno + 1
         line = adjustl(line)
         if (len_trim(line) == 0 .or. line(1:1) == "#") cycle
         read (line, *, iostat=ios) y
         if (ios /= 0 .or. .not. ieee_is_finite(y) .or. scan(trim(line), " ,;") > 0) then
            close (unit)
            call usage_error(tab, "--profile-file: line "//int_text(lineno)//" of '"//path// &
               "' is not one number (expected one height over Delta per line)")
         end if
         if (m == max_samples) then
            close (unit)
            call usage_error(tab, "--profile-file: more than 1000000 samples in '"//path//"'")
         end if
         if (m == size(samples)) then
            allocate (grown(2*m))
            grown(1:m) = samples
            call move_alloc(grown, samples)
         end if
         m = m + 1
         samples(m) = y
      end do
      close (unit)
      samples = samples(1:m)
   end subroutine read_samples

   !> The header lines every LJ table carries: the law and its parameter mapping, the
   !> grid and the profile.
   function lj_notes(opts, n_period, samples) result(notes)
      type(cli_options), intent(in) :: opts
      integer, intent(in) :: n_period
      real(wp), allocatable, intent(in) :: samples(:)
      character(len=160), allocatable :: notes(:)
      character(len=:), allocatable :: grid, profile
      grid = "N = "//int_text(n_period)//" grid points per period ("// &
         merge("--n        ", "automatic  ", given(opts, "--n"))
      grid = trim(grid)//")"
      if (allocated(samples)) then
         profile = "profile: "//int_text(size(samples))//" samples of one period from "// &
            opts%profile_file
      else
         profile = "profile: the sinusoid 1 - cos(2 pi x*)"
      end if
      notes = [character(len=160) :: &
         "Lennard-Jones 3-9 law, same work of adhesion dgamma = pi alpha^2/2 (p* Delta) and", &
         "range eps = dgamma/sigma0 (the MD opening h0): eps/Delta = 2 Dcod = "// &
         "(4 alpha^4)^(1/3)/mu,", &
         "so mu keeps its meaning; LJ's peak tension is then 16/(9 sqrt 3) sigma0 = "// &
         "1.0264 sigma0", grid, profile]
   end function lj_notes

   !> The problem of the options (a usage error for a bad --n or --profile-file, and for a
   !> grid cap exceeded: --n too large, or an automatic grid beyond its cap, which --n
   !> resolves; the C face's WA_INVALID_ARGUMENT).
   subroutine lj_setup(tab, opts, params, problem, n, samples)
      type(table_type), intent(inout) :: tab
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(lj_problem_type), intent(out) :: problem
      integer, intent(out) :: n
      real(wp), allocatable, intent(out) :: samples(:)
      character(len=256) :: msg
      integer :: status
      call lj_inputs(tab, opts, n, samples)
      msg = ""
      ! samples unallocated (the sinusoid) is an absent optional argument
      call lj_problem(params, problem, status, msg, n, samples)
      if (status == wa_capacity_too_small) status = wa_invalid_argument
      call check(tab, status, msg)
   end subroutine lj_setup

   !> A failed call: a usage error for a bad argument (exit 2), else a numerical error.
   subroutine check(tab, status, msg)
      type(table_type), intent(inout) :: tab
      integer, intent(in) :: status
      character(len=*), intent(in) :: msg
      if (status == wa_invalid_argument) call usage_error(tab, "--model lj: "// &
         option_message(trim(msg)))
      if (status /= wa_ok) call numerical_error(tab, status, msg)
   end subroutine check

   !> The cycle (both paths, P_fc, P_pf, W* with error estimates) of one (alpha, mu).
   subroutine cycle_of(opts, params, samples, cycle, status, msg)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      real(wp), allocatable, intent(in) :: samples(:)
      type(lj_cycle_type), intent(out) :: cycle
      integer, intent(out) :: status
      character(len=*), intent(inout) :: msg
      integer :: n
      n = 0
      if (given(opts, "--n")) n = opts%n_points
      call lj_cycle(params, cycle, status, msg, n, samples)
   end subroutine cycle_of

   !> branch --model lj: the traced curve from far apart to full contact.
   subroutine run_lj_branch(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: b, walked
      type(lj_cycle_type) :: cycle, coarse
      real(wp), allocatable :: samples(:)
      real(wp) :: err(3)
      character(len=300), allocatable :: notes(:)
      character(len=256) :: msg
      integer :: i, n, status
      call lj_setup(tab, opts, params, problem, n, samples)
      msg = ""
      call lj_trace(problem, b, status, msg)
      call check(tab, status, msg)
      ! the critical values on this curve (the paths insert their landing states into a
      ! copy), and their error estimates from the cycle at N/2
      walked = b
      err = ieee_value(err, ieee_quiet_nan)          ! NaN: a path or the coarse cycle failed
      call lj_paths(problem, walked, cycle, status, msg)
      if (status /= wa_ok) then                      ! the curve is still written
         cycle%p_fc = err(1); cycle%p_pf = err(1); cycle%w_star = err(1)
         msg = "(the paths failed: "//trim(msg)//")"
      else
         call lj_cycle(params, coarse, status, msg, b%n_period/2, samples, estimate=.false.)
      end if
      if (status == wa_ok) then
         err = abs([cycle%p_fc - coarse%p_fc, cycle%p_pf - coarse%p_pf, &
            cycle%w_star - coarse%w_star])
      else if (msg(1:1) /= "(") then
         msg = "(the cycle at N/2 failed: "//trim(msg)//")"
      end if
      call add_value(tab, "N", [real(b%n_period, wp)], integers=.true.)
      call add_value(tab, "P_fc", [cycle%p_fc])
      call add_value(tab, "P_fc_err", [err(1)])
      call add_value(tab, "P_pf", [cycle%p_pf])
      call add_value(tab, "P_pf_err", [err(2)])
      call add_value(tab, "W_star", [cycle%w_star])
      call add_value(tab, "W_star_err", [err(3)])
      notes = [character(len=300) :: lj_notes(opts, b%n_period, samples), &
         "a_star: half the measure of {h <= eps} (contact); b_star: half the measure of", &
         "  {h <= 3^(1/6) eps} (the position of the peak tension); gbar, h: over Delta", &
         "stable: 1 = stable under load control; stable_gap: 1 = under gap control", &
         "event: 0 none, 1 fold of P*, 14 fold of gbar*, 5 full contact reached or left,", &
         "       15 contact made or lost, 8 first and last point", &
         "extremum: +1/-1 maximum/minimum of P*, +2/-2 maximum/minimum of gbar*", &
         "on this curve: P_fc = "//format_real(cycle%p_fc)//"  P_fc_err = "// &
         format_real(err(1)), &
         "  P_pf = "//format_real(cycle%p_pf)//"  P_pf_err = "//format_real(err(2)), &
         "  W* = "//format_real(cycle%w_star)//"  W_star_err = "//format_real(err(3)), &
         "_err: discretisation-error estimate |value at N - value at N/2| (NaN: the", &
         "  cycle at N/2 failed); the points of the curve have none of their own"]
      if (status /= wa_ok) notes = [character(len=300) :: notes, msg]
      call write_header(tab, "equilibrium curve of the smooth (Lennard-Jones) model", "lj", &
         "a_star b_star P_star stable stable_gap event extremum gbar h_min h_max", params, &
         notes)
      do i = 1, b%n
         call write_row(tab, [b%a_star(i), b%b_star(i), b%p_star(i), &
            merge(1.0_wp, 0.0_wp, b%stable_load(i)), merge(1.0_wp, 0.0_wp, b%stable_gap(i)), &
            real(b%event(i), wp), real(b%extremum(i), wp), b%gbar(i), b%h_min(i), b%h_max(i)])
      end do
   end subroutine run_lj_branch

   !> path --model lj [--control gap]: the events of loading and unloading (load control)
   !> or of approach and retraction (gap control), with the critical values.
   subroutine run_lj_path(opts, params, tab, gap)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      logical, intent(in) :: gap
      type(lj_cycle_type) :: cycle
      type(lj_problem_type) :: problem
      type(lj_path_type) :: path
      real(wp), allocatable :: samples(:)
      character(len=160), allocatable :: notes(:)
      character(len=256) :: msg
      integer :: i, n, status
      call lj_setup(tab, opts, params, problem, n, samples)   ! checks --n, the profile
      msg = ""
      call cycle_of(opts, params, samples, cycle, status, msg)
      call check(tab, status, msg)
      notes = [character(len=160) :: lj_notes(opts, cycle%n_period, samples), &
         "event: 3 jump start, 4 jump end, 5 full contact reached, 6 full contact left,", &
         "       7 pull-off; a_star: half the measure of {h <= eps}; gbar over Delta", &
         "_err: discretisation-error estimate |value at N - value at N/2|"]
      call add_value(tab, "N", [real(cycle%n_period, wp)], integers=.true.)
      if (gap) then
         path = cycle%gap
         notes = [character(len=160) :: notes, &
            "stage: 1 approach (gbar* falling), 2 retraction (rising); jumps keep gbar*", &
            "energy lost per cycle W* = -oint P* dgbar* (units p* Delta):", &
            "W* = "//format_real(cycle%w_star)//"  W_star_err = "// &
            format_real(cycle%w_star_err)//"  W*/(pi alpha^2/2) = "// &
            format_real(cycle%w_fraction)]
         call add_value(tab, "W_star", [cycle%w_star])
         call add_value(tab, "W_star_err", [cycle%w_star_err])
         call add_value(tab, "W_fraction", [cycle%w_fraction])
      else
         path = cycle%load
         notes = [character(len=160) :: notes, &
            "stage: 1 loading, 2 unloading; jumps keep P*", &
            "P_fc = "//format_real(cycle%p_fc)//"  P_fc_err = "//format_real(cycle%p_fc_err), &
            "P_pf = "//format_real(cycle%p_pf)//"  P_pf_err = "//format_real(cycle%p_pf_err), &
            "P_snap = "//format_real(cycle%p_snap)//"  P_snap_err = "// &
            format_real(cycle%p_snap_err)//" (the last jump on loading)"]
         call add_value(tab, "P_fc", [cycle%p_fc])
         call add_value(tab, "P_pf", [cycle%p_pf])
         call add_value(tab, "P_fc_err", [cycle%p_fc_err])
         call add_value(tab, "P_pf_err", [cycle%p_pf_err])
         call add_value(tab, "P_snap", [cycle%p_snap])
         call add_value(tab, "P_snap_err", [cycle%p_snap_err])
      end if
      call write_header(tab, merge("gap-controlled approach and retraction", &
         "load-controlled loading and unloading ", gap), "lj", &
         "stage event a_star P_star gbar", params, notes)
      do i = 1, path%n
         call write_row(tab, [real(path%stage(i), wp), real(path%event(i), wp), &
            path%a_star(i), path%p_star(i), path%gbar(i)])
      end do
   end subroutine run_lj_path

   !> critical --model lj: P_fc, P_pf (load control) or W* (gap control) with their error
   !> estimates over alpha x mu; a failing row is written with NaN and named on stderr.
   subroutine run_lj_critical(opts, alpha, mu, tab, gap, rows_failed)
      type(cli_options), intent(in) :: opts
      real(wp), intent(in) :: alpha(:), mu(:)
      type(table_type), intent(inout) :: tab
      logical, intent(in) :: gap
      logical, intent(out) :: rows_failed
      type(lj_cycle_type), allocatable :: cycles(:, :)
      type(params_type) :: params
      type(lj_problem_type) :: problem
      type(progress_type) :: progress
      real(wp), allocatable :: samples(:)
      character(len=160), allocatable :: notes(:)
      character(len=256) :: msg
      character(len=:), allocatable :: why
      integer, allocatable :: row_stat(:, :)
      integer :: i, j, n, status, n_failed
      real(wp) :: nan

      nan = ieee_value(nan, ieee_quiet_nan)
      allocate (cycles(size(mu), size(alpha)), row_stat(size(mu), size(alpha)))
      msg = ""
      call lj_inputs(tab, opts, n, samples)
      ! a bad --n or profile is a usage error before any work (other failures: per row)
      call new_params(alpha(1), mu(1), params, status, msg)
      if (status == wa_ok) call lj_problem(params, problem, status, msg, n, samples)
      ! an --n beyond the grid's cap fails every row: a usage error too
      if (status == wa_capacity_too_small .and. n /= 0) status = wa_invalid_argument
      if (status == wa_invalid_argument) call check(tab, status, msg)
      n_failed = 0
      call progress_start(progress, "critical")
      do j = 1, size(alpha)
         do i = 1, size(mu)
            call progress_step(progress, (j - 1)*size(mu) + i - 1, size(mu)*size(alpha))
            msg = ""
            call new_params(alpha(j), mu(i), params, status, msg)
            if (status == wa_ok) call cycle_of(opts, params, samples, cycles(i, j), status, msg)
            row_stat(i, j) = status
            if (status == wa_ok) cycle
            n_failed = n_failed + 1
            call progress_end(progress)
            ! a cap of the solver ("lj: ...") is not an output array too small
            why = status_message(status)
            if (status == wa_capacity_too_small .and. index(msg, "lj: ") == 1) &
               why = "beyond the solver's caps"
            write (error_unit, '(a)') "wavyadhesion: critical: alpha = "// &
               format_real(alpha(j))//", mu = "//format_real(mu(i))//": "//why//": "// &
               trim(msg)//" (row written with NaN values)"
         end do
      end do
      call progress_end(progress)
      rows_failed = n_failed > 0
      call add_value(tab, "rows_failed", [real(n_failed, wp)], integers=.true.)
      notes = [character(len=160) :: lj_notes(opts, cycles(1, 1)%n_period, samples)]
      notes(4) = "N: grid points per period ("//merge("--n)      ", "automatic)", &
         given(opts, "--n"))//trim(grid_list(cycles, row_stat))
      notes = [character(len=160) :: notes, &
         "_err: discretisation-error estimate |value at N - value at N/2|"]
      if (gap) then
         notes = [character(len=160) :: notes, &
            "W_star: energy lost per gap-controlled cycle, -oint P* dgbar* (p* Delta)", &
            "W_fraction: W*/(pi alpha^2/2), the fraction of the work of adhesion"]
      else
         notes = [character(len=160) :: notes, &
            "P_fc: load at which full contact is first reached (loading from P* = 0)", &
            "P_pf: pull-off load on unloading from full contact", &
            "P_fc_peak: load at which b* (the peak tension's abscissa) first reaches 1/2: the", &
            "  full-contact load comparable with DW's and MD's P_fc (doc/theory.md)"]
      end if
      if (n_failed > 0) notes = [character(len=160) :: notes, int_text(n_failed)//" of "// &
         int_text(size(row_stat))//" rows failed: their values are NaN (reasons on standard error)"]
      if (gap) then
         call write_header(tab, "energy lost per gap-controlled cycle", "lj", &
            "alpha mu W_star W_fraction W_star_err", notes=notes)
      else
         call write_header(tab, "critical forces (full contact, pull-off)", "lj", &
            "alpha mu P_fc P_pf P_fc_err P_pf_err P_fc_peak P_fc_peak_err", notes=notes)
      end if
      do j = 1, size(alpha)
         do i = 1, size(mu)
            associate (c => cycles(i, j))
               if (row_stat(i, j) /= wa_ok .and. gap) then
                  call write_row(tab, [alpha(j), mu(i), nan, nan, nan])
               else if (row_stat(i, j) /= wa_ok) then
                  call write_row(tab, [alpha(j), mu(i), nan, nan, nan, nan, nan, nan])
               else if (gap) then
                  call write_row(tab, [alpha(j), mu(i), c%w_star, c%w_fraction, c%w_star_err])
               else
                  call write_row(tab, [alpha(j), mu(i), c%p_fc, c%p_pf, c%p_fc_err, c%p_pf_err, &
                     c%p_fc_peak, c%p_fc_peak_err])
               end if
            end associate
         end do
      end do
      if (rows_failed) write (error_unit, '(a,i0,a,i0,a)') "wavyadhesion: critical: ", &
         n_failed, " of ", size(row_stat), " rows failed (written with NaN values); exit status 1"
   end subroutine run_lj_critical

   !> ": N = 256" when every row that succeeded has the same grid, else the grids in row
   !> order.
   function grid_list(cycles, row_stat) result(text)
      type(lj_cycle_type), intent(in) :: cycles(:, :)
      integer, intent(in) :: row_stat(:, :)
      character(len=:), allocatable :: text
      integer :: i, j, first
      first = 0
      text = ""
      do j = 1, size(cycles, 2)
         do i = 1, size(cycles, 1)
            if (row_stat(i, j) /= wa_ok) cycle
            if (first == 0) first = cycles(i, j)%n_period
            if (len(text) > 0) text = text//","
            text = text//int_text(cycles(i, j)%n_period)
         end do
      end do
      if (all(pack(cycles%n_period, row_stat == wa_ok) == first)) text = int_text(first)
      text = ": N = "//text
   end function grid_list

   !> profile --model lj --a-star X: gap and traction over the period of the traced state
   !> with a* nearest X (among the load-stable states when there are any; lj_state_at_a),
   !> at the N grid nodes, x* from -1/2.
   subroutine run_lj_profile(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      type(lj_problem_type) :: problem
      type(lj_state_type) :: state
      real(wp), allocatable :: samples(:)
      character(len=256) :: msg
      real(wp) :: a_target
      integer :: i, n, status

      if (.not. allocated(opts%a_star)) call usage_error(tab, "profile needs --a-star X")
      a_target = single(tab, opts%a_star, "--a-star")
      if (.not. (a_target >= 0.0_wp .and. a_target <= 0.5_wp)) call usage_error(tab, &
         "--a-star: "//format_real(a_target)//" is outside its valid range [0, 1/2]")
      if (given(opts, "--c-star")) call usage_error(tab, "--c-star does not apply to "// &
         "--model lj (its states have no interaction-zone edge)")
      call lj_setup(tab, opts, params, problem, n, samples)
      msg = ""
      call lj_state_at_a(problem, a_target, state, status, msg)
      call check(tab, status, msg)
      call add_value(tab, "a_star", [state%a_star])
      call add_value(tab, "b_star", [state%b_star])
      call add_value(tab, "P_star", [state%p_star])
      call add_value(tab, "gbar", [state%gbar])
      call add_value(tab, "N", [real(state%n_period, wp)], integers=.true.)
      call write_header(tab, "gap and traction of one state of the smooth (Lennard-Jones) "// &
         "model", "lj", "x_star traction gap", params, [character(len=160) :: &
         lj_notes(opts, state%n_period, samples), &
         "state: the traced "//trim(merge("load-stable state ", "state             ", &
         state%stable_load))//" with a* nearest --a-star", &
         "a_star = "//format_real(state%a_star)//"  b_star = "//format_real(state%b_star), &
         "P_star = "//format_real(state%p_star)//"  gbar = "//format_real(state%gbar)// &
         " (mean gap over Delta)", &
         "traction: p/p* (positive = compressive); gap: h/Delta; at the N grid nodes"])
      do i = 1, state%n_period             ! from x* = -1/2, as the other models' profiles
         call write_row(tab, [state%x(i), state%traction(i), state%gap(i)])
      end do
   end subroutine run_lj_profile

end module wa_cli_lj
