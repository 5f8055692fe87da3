!> The library's version. The one source of the version number is the file VERSION at the
!> repository root (read by fpm.toml and python/meson.build); this constant is its copy for
!> Fortran and C, written by `bash tools/set_version.sh X.Y.Z` (which also sets VERSION and
!> CITATION.cff) and checked against VERSION by the C-interface test and test/docs.
module wa_release
   implicit none
   private

   !> Version of the library, e.g. "0.2.0" (semantic versioning)
   character(len=*), parameter, public :: wa_version = "0.2.0"

end module wa_release
