!> `wavyadhesion`: the command-line driver. Parses the options, opens the output, runs
!> the subcommand's driver and sets the exit status: 0 ok, 2 usage error, 1 numerical
!> failure or write error (the drivers exit themselves on a usage or numerical error,
!> discarding the table). `--output FILE` is replaced only when the whole table was
!> written (wa_cli_output).
program wavyadhesion_cli
   use, intrinsic :: iso_fortran_env, only: error_unit
   use wavyadhesion, only: params_type, wa_version
   use wa_cli_options, only: cli_options, parse_command_line, si_given
   use wa_cli_table, only: table_type, open_table, set_units, put_text, close_table
   use wa_cli_units, only: si_scales_type
   use wa_cli_common, only: usage_error, resolve_params
   use wa_cli_help, only: print_help
   use wa_cli_states, only: run_point, run_branch, run_profile
   use wa_cli_paths, only: run_path, run_gap_path, run_gaplaw
   use wa_cli_critical, only: run_critical, run_gap_critical
   use wa_cli_map, only: run_map
   use wa_cli_options, only: model_lj
   use wa_cli_lj, only: run_lj_branch, run_lj_path, run_lj_profile
   implicit none

   type(cli_options) :: opts
   character(len=:), allocatable :: error, control
   type(params_type) :: params
   type(si_scales_type) :: si
   !> Where the output goes; usage and numerical errors discard it
   type(table_type) :: tab
   logical :: ok, rows_failed, no_directory

   call parse_command_line(opts, error)
   if (allocated(error)) call usage_error(tab, error)
   if (opts%help .or. opts%version) then
      call open_table(tab, opts%format, "", ok)
      if (ok .and. opts%help) call print_help(tab, opts%help_topic)
      if (ok .and. .not. opts%help) call put_text(tab, "wavyadhesion "//wa_version)
      if (ok) call close_table(tab, ok)
      if (.not. ok) stop 1, quiet=.true.
      stop
   end if
   if ((opts%command /= "critical" .and. opts%command /= "map") .or. si_given(opts)) &
      call resolve_params(tab, opts, params, si)
   call open_table(tab, opts%format, opts%output, ok, no_directory)
   if (.not. ok .and. no_directory) then            ! a bad --output: a usage error
      write (error_unit, '(a)') "Try 'wavyadhesion --help'."
      stop 2, quiet=.true.
   end if
   if (.not. ok) stop 1, quiet=.true.               ! a write error (its reason is printed)

   call set_units(tab, opts%command, si, opts%units == "si")
   control = "load"
   if (allocated(opts%control)) control = opts%control
   rows_failed = .false.
   select case (opts%command)
   case ("point"); call run_point(opts, params, tab)
   case ("branch")
      if (opts%model == model_lj) then
         call run_lj_branch(opts, params, tab)
      else
         call run_branch(opts, params, tab)
      end if
   case ("profile")
      if (opts%model == model_lj) then
         call run_lj_profile(opts, params, tab)
      else
         call run_profile(opts, params, tab)
      end if
   case ("path")
      if (opts%model == model_lj) then
         call run_lj_path(opts, params, tab, control == "gap")
      else if (control == "gap") then
         call run_gap_path(opts, params, tab)
      else
         call run_path(opts, params, tab)
      end if
   case ("gaplaw"); call run_gaplaw(opts, params, tab)
   case ("critical")
      if (control == "gap") then
         call run_gap_critical(opts, params, tab, rows_failed)
      else
         call run_critical(opts, params, tab, rows_failed)
      end if
   case ("map"); call run_map(opts, tab)
   case default
      call usage_error(tab, "'"//opts%command//"' is not available in this version yet")
   end select
   call close_table(tab, ok)
   if (.not. ok) stop 1, quiet=.true.
   if (rows_failed) stop 1, quiet=.true.

end program wavyadhesion_cli
