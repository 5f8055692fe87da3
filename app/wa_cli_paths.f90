!> The CLI's path subcommands: `path` (loading and unloading under load control, or
!> approach and retraction under mean-gap control with --control gap) and `gaplaw` (P*
!> against the mean gap on a grid).
module wa_cli_paths
   use wa_kinds, only: wp
   use wa_text, only: int_text
   use wavyadhesion, only: params_type, path_type, branch_type, gap_path_type, trace_branch, &
      path_from_branch, load_jump_energies, gap_path, gap_law, event_jump_start, wa_ok
   use wa_cli_options, only: cli_options, model_name
   use wa_cli_table, only: table_type, add_value, write_header, write_row, format_real
   use wa_cli_progress, only: progress_type, progress_start, progress_step, progress_end
   use wa_cli_common, only: numerical_error, event_legend
   implicit none
   private

   public :: run_path, run_gap_path, run_gaplaw

contains

   !> path: the events of loading (stage 1) and unloading (stage 2).
   subroutine run_path(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      type(path_type) :: path
      type(branch_type) :: branch
      character(len=256) :: msg
      character(len=160), allocatable :: notes(:)
      real(wp) :: energy(64)
      integer, allocatable :: jumps(:)
      integer :: i, status

      msg = ""
      call trace_branch(opts%model, params, branch, status, msg)
      if (status /= wa_ok) call numerical_error(tab, status, msg)
      call path_from_branch(opts%model, params, branch, path, status, msg)
      if (status /= wa_ok) call numerical_error(tab, status, msg)
      call load_jump_energies(opts%model, params, branch, path, energy, status, msg)
      if (status /= wa_ok) call numerical_error(tab, status, msg)
      notes = [character(len=160) :: "stage: 1 loading, 2 unloading", event_legend(1), &
         event_legend(2), "P_fc = "//format_real(path%p_fc)//"  P_pf = "// &
         format_real(path%p_pf), "energy released by each jump (units p* Delta per period):"]
      do i = 1, path%n
         if (path%event(i) /= event_jump_start) cycle
         if (energy(i) == energy(i)) then
            notes = [character(len=160) :: notes, "  jump starting at event row "//int_text(i)// &
               ", P* = "//format_real(path%p_star(i))//": "//format_real(energy(i))]
         else                    ! NaN: the separated state is not on the branch
            notes = [character(len=160) :: notes, "  jump starting at event row "//int_text(i)// &
               ", P* = "//format_real(path%p_star(i))//": not defined", &
               "    (it leaves or lands on separated surfaces: a pull-off or a jump-in)"]
         end if
      end do
      notes = [character(len=160) :: notes, "P-a loop area (the paper's measure, not an "// &
         "energy) = "//format_real(path%loop_area)]
      jumps = pack([(i, i = 1, path%n)], path%event(1:path%n) == event_jump_start)
      call add_value(tab, "P_fc", [path%p_fc])
      call add_value(tab, "P_pf", [path%p_pf])
      call add_value(tab, "jump_rows", real(jumps, wp), list=.true., integers=.true.)
      call add_value(tab, "jump_energies", energy(jumps), list=.true.)
      call add_value(tab, "loop_area", [path%loop_area])
      call write_header(tab, "load-controlled loading and unloading", model_name(opts%model), &
         "stage event a_star c_star P_star", params, notes)
      do i = 1, path%n
         call write_row(tab, [real(path%stage(i), wp), real(path%event(i), wp), &
            path%a_star(i), path%c_star(i), path%p_star(i)])
      end do
   end subroutine run_path

   !> path --control gap: approach and retraction under mean-gap control.
   subroutine run_gap_path(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      type(gap_path_type) :: path
      character(len=256) :: msg
      integer :: i, status

      msg = ""
      call gap_path(opts%model, params, path, status, msg)
      if (status /= wa_ok) call numerical_error(tab, status, msg)
      call add_value(tab, "W_star", [path%w_star])
      call add_value(tab, "W_fraction", [path%w_fraction])
      call write_header(tab, "gap-controlled approach and retraction", &
         model_name(opts%model), "stage event a_star c_star P_star gbar", params, &
         [character(len=80) :: "stage: 1 approach (gbar* falling), 2 retraction (rising)", &
         "event: 3 jump start, 4 jump end (at constant gbar*), 5 full contact reached,", &
         "       6 full contact left, 10 first interaction (touch), 11 contact made,", &
         "       12 contact lost, 13 interaction lost (P* = 0 beyond)", &
         "energy lost per cycle W* = -oint P* dgbar* (units p* Delta):", &
         "W* = "//format_real(path%w_star)//"  W*/(pi alpha^2/2) = "// &
         format_real(path%w_fraction)])
      do i = 1, path%n
         call write_row(tab, [real(path%stage(i), wp), real(path%event(i), wp), &
            path%a_star(i), path%c_star(i), path%p_star(i), path%gbar(i)])
      end do
   end subroutine run_gap_path

   !> gaplaw: P* on approach and retraction and their slopes on a uniform gbar* grid,
   !> in calls of `chunk` mean gaps (the values equal those of one call) so that a long
   !> run can show its progress.
   subroutine run_gaplaw(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      integer, parameter :: chunk = 65536
      real(wp), allocatable :: pa(:), pr(:), da(:), dr(:)
      character(len=256) :: msg
      type(progress_type) :: progress
      integer :: i, n, k, status

      n = size(opts%gbar)
      allocate (pa(n), pr(n), da(n), dr(n))
      msg = ""
      call progress_start(progress, "gaplaw")
      do i = 1, n, chunk
         k = min(n, i + chunk - 1)
         call progress_step(progress, i - 1, n)
         call gap_law(opts%model, params, opts%gbar(i:k), pa(i:k), pr(i:k), da(i:k), &
            dr(i:k), status, msg)
         if (status /= wa_ok) call numerical_error(tab, status, msg)
      end do
      call progress_end(progress)
      call write_header(tab, "gap law: P* against the mean gap gbar* (gap control)", &
         model_name(opts%model), "gbar P_approach P_retract dPdg_approach dPdg_retract", &
         params, [character(len=80) :: &
         "P_approach: after approaching from far apart; P_retract: after", &
         "retracting from full contact (doc/user-guide.md, hysteresis convention);", &
         "P* = 0 and slope 0 where the surfaces do not interact"])
      do i = 1, n
         call write_row(tab, [opts%gbar(i), pa(i), pr(i), da(i), dr(i)])
      end do
   end subroutine run_gaplaw

end module wa_cli_paths
