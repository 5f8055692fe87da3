!> Writers for the CLI's tables (SPEC section 7): `table` has `#` comment lines and
!> purely numeric rows (reals in ES24.16E3) that Fortran list-directed READ accepts;
!> `csv` has one header row of column names, then the same numbers.
module wa_cli_table
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use wa_kinds, only: wp
   use wavyadhesion, only: params_type, wa_version
   use wa_cli_output, only: sink_type, put_line
   implicit none
   private

   public :: write_header, write_row, format_real

contains

   !> Comment block (table) or column-name row (csv).
   subroutine write_header(out, format, what, model, params, columns, notes)
      type(sink_type), intent(inout) :: out
      character(len=*), intent(in) :: format, what, model, columns
      type(params_type), intent(in), optional :: params
      character(len=*), intent(in), optional :: notes(:)
      integer :: i
      if (format == "csv") then
         call put_line(out, csv_names(columns))
         return
      end if
      call put_line(out, "# wavyadhesion "//wa_version//": "//what)
      call put_line(out, "# model: "//model)
      if (present(params)) then
         call put_line(out, "# alpha = "//format_real(params%alpha)//"  mu = "// &
            format_real(params%mu))
         call put_line(out, "# Sigma0 = "//format_real(params%sigma0)//"  Dcod = "// &
            format_real(params%dcod))
      end if
      if (present(notes)) then
         do i = 1, size(notes)
            call put_line(out, "# "//trim(notes(i)))
         end do
      end if
      call put_line(out, "# columns: "//columns)
   end subroutine write_header

   !> One row: reals, integers, then the reals of `tail`, separated by blanks (table) or
   !> commas (csv).
   subroutine write_row(out, format, reals, ints, prefix, tail)
      type(sink_type), intent(inout) :: out
      character(len=*), intent(in) :: format
      real(wp), intent(in) :: reals(:)
      integer, intent(in), optional :: ints(:)
      !> Text before the reals (e.g. integer columns that come first)
      character(len=*), intent(in), optional :: prefix
      !> Reals after the integers (e.g. gbar at the end of point and branch rows)
      real(wp), intent(in), optional :: tail(:)
      character(len=:), allocatable :: line, sep
      character(len=12) :: itext
      integer :: i
      sep = " "
      if (format == "csv") sep = ","
      line = ""
      if (present(prefix)) line = prefix
      do i = 1, size(reals)
         if (i > 1) line = line//sep
         line = line//adjustr_field(format_real(reals(i)), format)
      end do
      if (present(ints)) then
         do i = 1, size(ints)
            write (itext, '(i0)') ints(i)
            line = line//sep//trim(itext)
         end do
      end if
      if (present(tail)) then
         do i = 1, size(tail)
            line = line//sep//adjustr_field(format_real(tail(i)), format)
         end do
      end if
      call put_line(out, line)
   end subroutine write_row

   !> ES24.16E3, or Infinity / -Infinity / NaN spelled so strtod and float() read them.
   function format_real(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=24) :: buf
      if (ieee_is_nan(x)) then
         text = "NaN"
      else if (.not. ieee_is_finite(x)) then
         text = merge("Infinity ", "-Infinity", x > 0.0_wp)
         text = trim(text)
      else
         write (buf, '(es24.16e3)') x
         text = trim(adjustl(buf))
      end if
   end function format_real

   function adjustr_field(text, format) result(field)
      character(len=*), intent(in) :: text, format
      character(len=:), allocatable :: field
      if (format == "csv" .or. len(text) >= 24) then
         field = text
      else
         field = repeat(" ", 24 - len(text))//text
      end if
   end function adjustr_field

   function csv_names(columns) result(names)
      character(len=*), intent(in) :: columns
      character(len=:), allocatable :: names
      integer :: i
      names = trim(adjustl(columns))
      do i = 1, len(names)
         if (names(i:i) == " ") names(i:i) = ","
      end do
   end function csv_names

end module wa_cli_table
