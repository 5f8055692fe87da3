!> The CLI's `map` subcommand: the boundary curves of the adhesion map as rows
!> "boundary alpha mu" (boundary: the integer code, meanings in the header), each curve
!> in increasing alpha.
module wa_cli_map
   use wa_kinds, only: wp
   use wa_text, only: int_text
   use wavyadhesion, only: map_type, adhesion_map, boundary_meaning, special_meaning, &
      model_dw, model_md, map_control_load, map_control_gap, map_control_both, wa_ok, &
      wa_invalid_argument
   use wa_cli_options, only: cli_options, model_name
   use wa_cli_table, only: table_type, write_header, write_row, format_real
   use wa_cli_common, only: usage_error, numerical_error
   use wa_cli_progress, only: progress_type, progress_start, progress_note, progress_end
   implicit none
   private

   public :: run_map

contains

   subroutine run_map(opts, tab)
      type(cli_options), intent(in) :: opts
      type(table_type), intent(inout) :: tab
      real(wp), allocatable :: alpha(:), mu(:)
      type(map_type) :: map
      character(len=256) :: msg
      character(len=400), allocatable :: notes(:)
      character(len=*), parameter :: ends(0:3) = [character(len=24) :: "grid edge", &
         "inside (meets/turns)", "leaves the mu range", "load path fails"]
      type(progress_type) :: progress
      integer :: status, c, i, k, control
      logical :: seen

      control = map_control_load
      if (allocated(opts%control)) then
         if (opts%control == "gap") control = map_control_gap
         if (opts%control == "both") control = map_control_both
      end if
      alpha = [(10.0_wp**(-2.0_wp + 3.0_wp*real(i - 1, wp)/199.0_wp), i = 1, 200)]
      mu = [1.0e-3_wp, 1.0e3_wp]
      if (allocated(opts%alpha)) alpha = opts%alpha
      if (allocated(opts%mu)) mu = opts%mu
      if (opts%model /= model_dw .and. opts%model /= model_md) &
         call usage_error(tab, "map: --model must be dw or md (westergaard and jkr have one "// &
         "mechanism each)")
      if (size(mu) < 2) call usage_error(tab, "map: --mu-range needs N >= 2")
      msg = ""
      ! One library call that cannot report its progress: say so, and erase it after.
      call progress_start(progress, "map")
      call progress_note(progress, "computing the boundaries over "//int_text(size(alpha))// &
         " alpha (one library call; no progress until it returns)...")
      call adhesion_map(opts%model, alpha, mu(1), mu(size(mu)), max(size(mu), 60), map, &
         status, msg, control=control)
      call progress_end(progress)
      if (status == wa_invalid_argument) call usage_error(tab, "map: "//trim(msg))
      if (status /= wa_ok) call numerical_error(tab, status, msg)
      allocate (notes(0))
      do c = 1, map%n_boundaries
         seen = .false.
         do k = 1, c - 1
            seen = seen .or. map%boundary(k)%code == map%boundary(c)%code
         end do
         if (.not. seen) notes = [character(len=400) :: notes, "boundary "// &
            int_text(map%boundary(c)%code)//" = "//boundary_meaning(map%boundary(c)%code)]
      end do
      notes = [character(len=400) :: notes, &
         "boundary code = 100*which + 10*(mechanism below) + (mechanism above) in mu;", &
         "which 1 full contact, 2 pull-off (load control): mechanism 0 gradual, 1 jump "// &
         "case 1, 2 jump case 2, 3 snap at P=0;", &
         "which 3 approach, 4 retraction (gap control, --control gap|both): mechanism "// &
         "1 (flag) contact made/lost by a jump,", &
         "  2 (flag) jump(s) between states with contact (approach: at gbar* minima; "// &
         "retraction: before contact is lost)", &
         "each point located to 2e-9 relative in mu"]
      do c = 1, map%n_boundaries
         associate (b => map%boundary(c))
            notes = [character(len=400) :: notes, "curve "//int_text(c)//" ("// &
               int_text(b%code)//"): starts alpha "//format_real(b%alpha(1))//" mu "// &
               format_real(b%mu(1))//" ["//trim(ends(b%start_kind))//"], ends alpha "// &
               format_real(b%alpha(b%n))//" mu "//format_real(b%mu(b%n))//" ["// &
               trim(ends(b%end_kind))//"]"]
         end associate
      end do
      do c = 1, map%n_special
         notes = [character(len=400) :: notes, "special point "//int_text(c)//": alpha "// &
            format_real(map%special(c)%alpha)//" mu "//format_real(map%special(c)%mu)// &
            ": "//special_meaning(map%special(c))]
      end do
      call write_header(tab, "adhesion map: mechanism boundaries mu_b(alpha)", &
         model_name(opts%model), columns="boundary alpha mu", notes=notes)
      do c = 1, map%n_boundaries
         do i = 1, map%boundary(c)%n
            call write_row(tab, [real(map%boundary(c)%code, wp), map%boundary(c)%alpha(i), &
               map%boundary(c)%mu(i)])
         end do
      end do
   end subroutine run_map

end module wa_cli_map
