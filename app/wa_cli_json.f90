!> JSON text for the CLI's `--format json`: strings with escapes, numbers, and the
!> non-finite values, which JSON cannot hold as numbers: NaN, Infinity and -Infinity
!> are written as the strings "NaN", "Infinity", "-Infinity" (Python's float() and
!> numpy's asarray(..., dtype=float) read them; strict parsers accept the document).
module wa_cli_json
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_kinds, only: wp
   use wa_text, only: real_text, int_text
   implicit none
   private

   public :: json_string, json_real, json_int, json_real_list, nonfinite_note

   character(len=*), parameter :: nonfinite_note = "JSON has no NaN or infinite numbers: "// &
      "they are the strings ""NaN"", ""Infinity"", ""-Infinity"" (float() reads them)"

contains

   !> "text" with \" \\ and control characters escaped.
   pure function json_string(text) result(out)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: out
      character(len=6) :: code
      integer :: i, c
      out = '"'
      do i = 1, len(text)
         c = iachar(text(i:i))
         if (text(i:i) == '"' .or. text(i:i) == "\") then
            out = out//"\"//text(i:i)
         else if (c < 32) then
            write (code, '(a,z4.4)') "\u", c
            out = out//code
         else
            out = out//text(i:i)
         end if
      end do
      out = out//'"'
   end function json_string

   !> A real as a JSON number (ES24.16E3, which is valid JSON), or "NaN", "Infinity",
   !> "-Infinity" as strings.
   pure function json_real(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      if (x /= x) then
         text = '"NaN"'
      else if (.not. ieee_is_finite(x)) then
         text = merge('"Infinity" ', '"-Infinity"', x > 0.0_wp)
         text = trim(text)
      else
         text = real_text(x)
      end if
   end function json_real

   !> An integer as a JSON number.
   pure function json_int(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      text = int_text(i)
   end function json_int

   !> [x1, x2, ...], as integers when `integers`. Built in one pass over a buffer that
   !> doubles: a column of 10^5 values stays linear.
   pure function json_real_list(x, integers) result(text)
      real(wp), intent(in) :: x(:)
      logical, intent(in) :: integers
      character(len=:), allocatable :: text, item, grown
      integer :: i, n
      allocate (character(len=32*size(x) + 2) :: text)
      text(1:1) = "["
      n = 1
      do i = 1, size(x)
         if (integers) then
            item = json_int(nint(x(i)))
         else
            item = json_real(x(i))
         end if
         if (i > 1) item = ", "//item
         if (n + len(item) + 1 > len(text)) then
            allocate (character(len=2*len(text) + len(item)) :: grown)
            grown(1:n) = text(1:n)
            call move_alloc(grown, text)
         end if
         text(n + 1:n + len(item)) = item
         n = n + len(item)
      end do
      text = text(1:n)//"]"
   end function json_real_list

end module wa_cli_json
