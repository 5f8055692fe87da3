!> The CLI's `critical` subcommand: P_fc and P_pf over alpha x mu (load control), or the
!> critical values of mean-gap control (--control gap). A failing (alpha, mu) never loses
!> the table: its row is written with NaN values, standard error names it with its
!> reason, and rows_failed makes the exit status 1 once the whole table is written.
module wa_cli_critical
   use, intrinsic :: iso_fortran_env, only: error_unit
   use wa_kinds, only: wp
   use wavyadhesion, only: params_type, new_params, critical_sweep, gap_critical_sweep, &
      mechanism_change, gap_critical_count, gap_critical_names, status_message, wa_ok
   use wa_cli_options, only: cli_options, model_name, si_given, option_message, model_lj
   use wa_cli_table, only: table_type, add_value, write_header, write_row, format_real
   use wa_cli_progress, only: progress_type, progress_start, progress_step, progress_status, &
      progress_end
   use wa_text, only: int_text
   use wa_cli_common, only: usage_error
   use wa_cli_lj, only: run_lj_critical
   implicit none
   private

   public :: run_critical, run_gap_critical

contains

   !> critical: P_fc and P_pf over alpha x mu.
   subroutine run_critical(opts, si_params, tab, rows_failed)
      type(cli_options), intent(in) :: opts
      !> alpha and mu from the SI options (when given)
      type(params_type), intent(in) :: si_params
      type(table_type), intent(inout) :: tab
      logical, intent(out) :: rows_failed
      real(wp), allocatable :: alpha(:), mu(:), p_fc(:, :), p_pf(:, :)
      integer, allocatable :: fc_mech(:, :), pf_mech(:, :), row_stat(:)
      character(len=256), allocatable :: row_msg(:)
      character(len=256) :: msg
      type(progress_type) :: progress
      integer :: i, j, status, n_failed

      call critical_grid(tab, opts, si_params, alpha, mu)
      if (opts%model == model_lj) then
         call run_lj_critical(opts, alpha, mu, tab, .false., rows_failed)
         return
      end if
      msg = ""
      allocate (p_fc(size(mu), size(alpha)), p_pf(size(mu), size(alpha)), &
         fc_mech(size(mu), size(alpha)), pf_mech(size(mu), size(alpha)), &
         row_stat(size(mu)), row_msg(size(mu)))
      call progress_start(progress, "critical")
      n_failed = 0
      do j = 1, size(alpha)
         do i = 1, size(mu)                  ! one mu per call: the rows are independent
            call progress_step(progress, (j - 1)*size(mu) + i - 1, size(p_fc))
            call critical_sweep(opts%model, alpha(j), mu(i:i), p_fc(i:i, j), p_pf(i:i, j), &
               fc_mech(i:i, j), pf_mech(i:i, j), status, msg, row_stat(i:i), row_msg(i:i))
         end do
         if (any(row_stat /= wa_ok)) call progress_end(progress)
         call report_failed_rows(alpha(j), mu, row_stat, row_msg, "forces", n_failed)
      end do
      rows_failed = n_failed > 0
      call add_value(tab, "rows_failed", [real(n_failed, wp)], integers=.true.)
      call write_header(tab, "critical forces (full contact, pull-off)", &
         model_name(opts%model), "alpha mu P_fc P_pf", notes=[character(len=400) :: &
         "P_fc: load at which full contact is first reached (loading from P* = 0)", &
         "P_pf: pull-off load on unloading from full contact (-Infinity: never)", &
         failure_note(n_failed, size(p_fc)), &
         mechanism_notes(tab, opts, alpha, mu, fc_mech, pf_mech, progress)])
      call progress_end(progress)
      do j = 1, size(alpha)
         do i = 1, size(mu)
            call write_row(tab, [alpha(j), mu(i), p_fc(i, j), p_pf(i, j)])
         end do
      end do
      if (rows_failed) write (error_unit, '(a,i0,a,i0,a)') "wavyadhesion: critical: ", &
         n_failed, " of ", size(p_fc), " rows failed (written with NaN forces); exit status 1"
   end subroutine run_critical

   !> critical --control gap: the critical values of mean-gap control over alpha x mu
   !> (gap_critical_sweep); failing rows as in run_critical (NaN, reason on stderr).
   subroutine run_gap_critical(opts, si_params, tab, rows_failed)
      type(cli_options), intent(in) :: opts
      !> alpha and mu from the SI options (when given)
      type(params_type), intent(in) :: si_params
      type(table_type), intent(inout) :: tab
      logical, intent(out) :: rows_failed
      real(wp), allocatable :: alpha(:), mu(:), values(:, :, :)
      integer, allocatable :: row_stat(:)
      character(len=256), allocatable :: row_msg(:)
      character(len=256) :: msg
      character(len=24) :: t_fail, t_all
      character(len=400), allocatable :: notes(:)
      type(progress_type) :: progress
      integer :: i, j, status, n_failed

      call critical_grid(tab, opts, si_params, alpha, mu)
      if (opts%model == model_lj) then
         call run_lj_critical(opts, alpha, mu, tab, .true., rows_failed)
         return
      end if
      msg = ""
      allocate (values(gap_critical_count, size(mu), size(alpha)), row_stat(size(mu)), &
         row_msg(size(mu)))
      call progress_start(progress, "critical")
      n_failed = 0
      do j = 1, size(alpha)
         do i = 1, size(mu)                  ! one mu per call: the rows are independent
            call progress_step(progress, (j - 1)*size(mu) + i - 1, size(mu)*size(alpha))
            call gap_critical_sweep(opts%model, alpha(j), mu(i:i), values(:, i:i, j), status, &
               msg, row_stat(i:i), row_msg(i:i))
         end do
         if (any(row_stat /= wa_ok)) call progress_end(progress)
         call report_failed_rows(alpha(j), mu, row_stat, row_msg, "values", n_failed)
      end do
      call progress_end(progress)
      rows_failed = n_failed > 0
      call add_value(tab, "rows_failed", [real(n_failed, wp)], integers=.true.)
      write (t_fail, '(i0)') n_failed
      write (t_all, '(i0)') size(mu)*size(alpha)
      notes = [character(len=400) :: &
         "g_touch: gbar* where the approach first feels the surface (P* = 0 above)", &
         "P_jump_in, a_jump_in: P* and a* where the approach lands when it jumps at", &
         "  g_touch (a jump keeps gbar*); 0 and 0: no jump (P* leaves 0 gradually)", &
         "g_contact: gbar* where contact is first made on the approach", &
         "P_min, g_P_min, a_P_min: the most tensile load on the retraction and its", &
         "  gbar* and a* (jkr: -Infinity at full contact)", &
         "g_contact_lost, P_contact_lost: gbar* where contact is lost for good on the", &
         "  retraction and P* of the last state with contact", &
         "g_interaction_lost: gbar* beyond which P* = 0 on the retraction"]
      if (n_failed > 0) notes = [character(len=400) :: notes, trim(t_fail)//" of "// &
         trim(t_all)//" rows failed: their values are NaN (reasons on standard error)"]
      call write_header(tab, "critical values under mean-gap control "// &
         "(approach, retraction)", model_name(opts%model), &
         columns="alpha mu "//gap_critical_names, notes=notes)
      do j = 1, size(alpha)
         do i = 1, size(mu)
            call write_row(tab, [alpha(j), mu(i), values(:, i, j)])
         end do
      end do
      if (rows_failed) write (error_unit, '(a,i0,a,i0,a)') "wavyadhesion: critical: ", &
         n_failed, " of ", size(mu)*size(alpha), " rows failed (written with NaN values); "// &
         "exit status 1"
   end subroutine run_gap_critical

   !> Name each failed row of one alpha on standard error and count it.
   subroutine report_failed_rows(alpha, mu, row_stat, row_msg, what, n_failed)
      real(wp), intent(in) :: alpha, mu(:)
      integer, intent(in) :: row_stat(:)
      character(len=*), intent(in) :: row_msg(:), what
      integer, intent(inout) :: n_failed
      integer :: i
      do i = 1, size(mu)
         if (row_stat(i) == wa_ok) cycle
         n_failed = n_failed + 1
         write (error_unit, '(a)') "wavyadhesion: critical: alpha = "// &
            format_real(alpha)//", mu = "//format_real(mu(i))//": "// &
            status_message(row_stat(i))//": "//trim(row_msg(i))// &
            " (row written with NaN "//what//")"
      end do
   end subroutine report_failed_rows

   !> A header line saying how many rows failed (none when every row succeeded).
   function failure_note(n_failed, n_rows) result(notes)
      integer, intent(in) :: n_failed, n_rows
      character(len=400), allocatable :: notes(:)
      character(len=24) :: a, b
      allocate (notes(0))
      if (n_failed == 0) return
      write (a, '(i0)') n_failed
      write (b, '(i0)') n_rows
      notes = [character(len=400) :: trim(a)//" of "//trim(b)//" rows failed: their P_fc "// &
         "and P_pf are NaN (reasons on standard error)"]
   end function failure_note

   !> Header lines locating in mu each change of mechanism (table and json formats),
   !> between consecutive rows that succeeded. A change that cannot be located to 1e-10
   !> (the load path fails inside the bracket) is given as the interval known to hold it.
   function mechanism_notes(tab, opts, alpha, mu, fc_mech, pf_mech, progress) result(notes)
      type(table_type), intent(in) :: tab
      type(cli_options), intent(in) :: opts
      real(wp), intent(in) :: alpha(:), mu(:)
      integer, intent(in) :: fc_mech(:, :), pf_mech(:, :)
      type(progress_type), intent(inout) :: progress
      character(len=400), allocatable :: notes(:)
      character(len=*), parameter :: names(0:3) = [character(len=12) :: "gradual", &
         "jump case 1", "jump case 2", "snap at P=0"]
      character(len=256) :: msg
      character(len=:), allocatable :: where, change
      real(wp) :: mu_c, bracket(2)
      integer :: i, k, j, which, status, m(2)
      allocate (notes(0))
      if (tab%format == "csv") return
      do j = 1, size(alpha)
         i = next_good(fc_mech(:, j), 0)
         do while (i > 0)
            k = next_good(fc_mech(:, j), i)
            if (k == 0) exit
            do which = 1, 2
               if (which == 1) m = [fc_mech(i, j), fc_mech(k, j)]
               if (which == 2) m = [pf_mech(i, j), pf_mech(k, j)]
               if (m(1) == m(2)) cycle
               call progress_status(progress, "locating the mechanism changes (alpha "// &
                  int_text(j)//" of "//int_text(size(alpha))//")")
               msg = ""
               call mechanism_change(opts%model, alpha(j), which, mu(i), mu(k), mu_c, status, &
                  msg, bracket)
               change = merge(" P_fc: ", " P_pf: ", which == 1)//trim(names(m(1)))//" -> "// &
                  trim(names(m(2)))
               if (status == wa_ok) then
                  where = " mu "//format_real(mu_c)
               else
                  where = " mu in ["//format_real(bracket(1))//", "//format_real(bracket(2))//"]"
                  call progress_end(progress)
                  write (error_unit, '(a)') "wavyadhesion: critical: alpha = "// &
                     format_real(alpha(j))//":"//where//change//": "//trim(msg)
                  change = change//" (not located further: the load path fails there)"
               end if
               notes = [character(len=400) :: notes, "alpha "//format_real(alpha(j))//where// &
                  change]
            end do
            i = k
         end do
      end do
   end function mechanism_notes

   !> The next row after i whose forces were computed (mechanism >= 0), 0 when none.
   pure integer function next_good(mechanism, i)
      integer, intent(in) :: mechanism(:), i
      integer :: r
      next_good = 0
      do r = i + 1, size(mechanism)
         if (mechanism(r) >= 0) then
            next_good = r
            return
         end if
      end do
   end function next_good

   !> The alpha and mu of `critical` (both controls): defaults 0.3 and 1, the SI options,
   !> then --alpha and --mu / --mu-range; every value checked before any work.
   subroutine critical_grid(tab, opts, si_params, alpha, mu)
      type(table_type), intent(inout) :: tab
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: si_params
      real(wp), allocatable, intent(out) :: alpha(:), mu(:)
      type(params_type) :: params
      character(len=256) :: msg
      integer :: i, status
      alpha = [0.3_wp]
      mu = [1.0_wp]
      if (si_given(opts)) then
         alpha = [si_params%alpha]
         mu = [si_params%mu]
      end if
      if (allocated(opts%alpha)) alpha = opts%alpha
      if (allocated(opts%mu)) mu = opts%mu
      msg = ""
      do i = 1, size(alpha)
         call new_params(alpha(i), 1.0_wp, params, status, msg)
         if (status /= wa_ok) call usage_error(tab, option_message(trim(msg)))
      end do
      do i = 1, size(mu)
         call new_params(1.0_wp, mu(i), params, status, msg)
         if (status /= wa_ok) call usage_error(tab, option_message(trim(msg)))
      end do
   end subroutine critical_grid

end module wa_cli_critical
