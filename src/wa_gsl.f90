!> display: none
!>
!> Raw `bind(C)` interfaces to the parts of GSL the library uses. Not re-exported.
!>
!> The `_e` variants return a GSL status instead of calling the error handler on
!> domain errors; `gsl_set_error_handler_off` makes the remaining paths return too,
!> instead of calling abort() (which would kill a host Python process).
module wa_gsl
   use, intrinsic :: iso_c_binding, only: c_double, c_int, c_ptr, c_funptr, c_size_t
   implicit none
   private

   integer(c_int), parameter, public :: gsl_success = 0
   !> GSL_PREC_DOUBLE (a gsl_mode_t): full double precision.
   integer(c_int), parameter, public :: gsl_prec_double = 0

   !> gsl_sf_result
   type, bind(C), public :: gsl_sf_result
      real(c_double) :: val
      real(c_double) :: err
   end type gsl_sf_result

   !> gsl_function: a C function pointer and its context pointer.
   type, bind(C), public :: gsl_function
      type(c_funptr) :: function
      type(c_ptr) :: params
   end type gsl_function

   public :: gsl_sf_ellint_rf_e, gsl_sf_ellint_rd_e, gsl_sf_ellint_rj_e
   public :: gsl_sf_ellint_rf, gsl_sf_ellint_rd, gsl_sf_ellint_rj
   public :: gsl_set_error_handler_off
   public :: quad_istar_carlson, quad_istar_qag, quad_psi_k
   public :: gsl_sf_clausen
   public :: gsl_integration_workspace_alloc, gsl_integration_workspace_free
   public :: gsl_integration_qaws_table_alloc, gsl_integration_qaws_table_free
   public :: gsl_integration_qaws, gsl_integration_qag, gsl_integration_qags

   interface
      !> Carlson R_F(x, y, z).
      function gsl_sf_ellint_rf_e(x, y, z, mode, result) result(status) &
            bind(C, name="gsl_sf_ellint_RF_e")
         import :: c_double, c_int, gsl_sf_result
         real(c_double), value, intent(in) :: x, y, z
         integer(c_int), value, intent(in) :: mode
         type(gsl_sf_result), intent(out) :: result
         integer(c_int) :: status
      end function gsl_sf_ellint_rf_e

      !> Carlson R_D(x, y, z).
      function gsl_sf_ellint_rd_e(x, y, z, mode, result) result(status) &
            bind(C, name="gsl_sf_ellint_RD_e")
         import :: c_double, c_int, gsl_sf_result
         real(c_double), value, intent(in) :: x, y, z
         integer(c_int), value, intent(in) :: mode
         type(gsl_sf_result), intent(out) :: result
         integer(c_int) :: status
      end function gsl_sf_ellint_rd_e

      !> Carlson R_J(x, y, z, p).
      function gsl_sf_ellint_rj_e(x, y, z, p, mode, result) result(status) &
            bind(C, name="gsl_sf_ellint_RJ_e")
         import :: c_double, c_int, gsl_sf_result
         real(c_double), value, intent(in) :: x, y, z, p
         integer(c_int), value, intent(in) :: mode
         type(gsl_sf_result), intent(out) :: result
         integer(c_int) :: status
      end function gsl_sf_ellint_rj_e

      !> R_F, R_D, R_J returning the value (NaN on a domain error once the abort
      !> handler is off); pure, so usable from elemental code.
      pure function gsl_sf_ellint_rf(x, y, z, mode) result(r) bind(C, name="gsl_sf_ellint_RF")
         import :: c_double, c_int
         real(c_double), value, intent(in) :: x, y, z
         integer(c_int), value, intent(in) :: mode
         real(c_double) :: r
      end function gsl_sf_ellint_rf

      pure function gsl_sf_ellint_rd(x, y, z, mode) result(r) bind(C, name="gsl_sf_ellint_RD")
         import :: c_double, c_int
         real(c_double), value, intent(in) :: x, y, z
         integer(c_int), value, intent(in) :: mode
         real(c_double) :: r
      end function gsl_sf_ellint_rd

      pure function gsl_sf_ellint_rj(x, y, z, p, mode) result(r) bind(C, name="gsl_sf_ellint_RJ")
         import :: c_double, c_int
         real(c_double), value, intent(in) :: x, y, z, p
         integer(c_int), value, intent(in) :: mode
         real(c_double) :: r
      end function gsl_sf_ellint_rj

      !> Clausen function Cl_2(x) = -int_0^x ln|2 sin(t/2)| dt; pure, for elemental code.
      pure function gsl_sf_clausen(x) result(r) bind(C, name="gsl_sf_clausen")
         import :: c_double
         real(c_double), value, intent(in) :: x
         real(c_double) :: r
      end function gsl_sf_clausen

      !> Replace GSL's abort-on-error handler by "return the status".
      function gsl_set_error_handler_off() result(previous) &
            bind(C, name="gsl_set_error_handler_off")
         import :: c_funptr
         type(c_funptr) :: previous
      end function gsl_set_error_handler_off

      !> The GSL-based alternatives of wa_quadrature (which defines them, bind(C)), seen
      !> as what they are from the caller's side: pure functions of their value
      !> arguments (each allocates and frees its own workspace and switches GSL's abort
      !> handler off; NaN where GSL fails), so that the options
      !> of the pure dw_equilibrium and md_equilibrium can select them.
      pure function quad_istar_carlson(a, c, d2, omc2) result(w) &
            bind(C, name="wa_quad_istar_carlson")
         import :: c_double
         real(c_double), value, intent(in) :: a, c, d2, omc2
         real(c_double) :: w
      end function quad_istar_carlson

      pure function quad_istar_qag(a, c, d2, omc2, tol) result(w) &
            bind(C, name="wa_quad_istar_qag")
         import :: c_double
         real(c_double), value, intent(in) :: a, c, d2, omc2, tol
         real(c_double) :: w
      end function quad_istar_qag

      pure function quad_psi_k(method, k2, s2, omk2, cs2, tol) result(k) &
            bind(C, name="wa_quad_psi_k")
         import :: c_double, c_int
         integer(c_int), value, intent(in) :: method
         real(c_double), value, intent(in) :: k2, s2, omk2, cs2, tol
         real(c_double) :: k
      end function quad_psi_k

      function gsl_integration_workspace_alloc(n) result(w) &
            bind(C, name="gsl_integration_workspace_alloc")
         import :: c_size_t, c_ptr
         integer(c_size_t), value :: n
         type(c_ptr) :: w
      end function gsl_integration_workspace_alloc

      subroutine gsl_integration_workspace_free(w) &
            bind(C, name="gsl_integration_workspace_free")
         import :: c_ptr
         type(c_ptr), value :: w
      end subroutine gsl_integration_workspace_free

      !> Table for weight (x-a)^alpha (b-x)^beta log^mu(x-a) log^nu(b-x).
      function gsl_integration_qaws_table_alloc(alpha, beta, mu, nu) result(t) &
            bind(C, name="gsl_integration_qaws_table_alloc")
         import :: c_double, c_int, c_ptr
         real(c_double), value :: alpha, beta
         integer(c_int), value :: mu, nu
         type(c_ptr) :: t
      end function gsl_integration_qaws_table_alloc

      subroutine gsl_integration_qaws_table_free(t) &
            bind(C, name="gsl_integration_qaws_table_free")
         import :: c_ptr
         type(c_ptr), value :: t
      end subroutine gsl_integration_qaws_table_free

      function gsl_integration_qaws(f, a, b, t, epsabs, epsrel, limit, workspace, &
            result, abserr) result(status) bind(C, name="gsl_integration_qaws")
         import :: gsl_function, c_double, c_size_t, c_ptr, c_int
         type(gsl_function), intent(in) :: f
         real(c_double), value :: a, b
         type(c_ptr), value :: t
         real(c_double), value :: epsabs, epsrel
         integer(c_size_t), value :: limit
         type(c_ptr), value :: workspace
         real(c_double), intent(out) :: result, abserr
         integer(c_int) :: status
      end function gsl_integration_qaws

      function gsl_integration_qag(f, a, b, epsabs, epsrel, limit, key, workspace, &
            result, abserr) result(status) bind(C, name="gsl_integration_qag")
         import :: gsl_function, c_double, c_size_t, c_ptr, c_int
         type(gsl_function), intent(in) :: f
         real(c_double), value :: a, b
         real(c_double), value :: epsabs, epsrel
         integer(c_size_t), value :: limit
         integer(c_int), value :: key
         type(c_ptr), value :: workspace
         real(c_double), intent(out) :: result, abserr
         integer(c_int) :: status
      end function gsl_integration_qag

      function gsl_integration_qags(f, a, b, epsabs, epsrel, limit, workspace, &
            result, abserr) result(status) bind(C, name="gsl_integration_qags")
         import :: gsl_function, c_double, c_size_t, c_ptr, c_int
         type(gsl_function), intent(in) :: f
         real(c_double), value :: a, b
         real(c_double), value :: epsabs, epsrel
         integer(c_size_t), value :: limit
         type(c_ptr), value :: workspace
         real(c_double), intent(out) :: result, abserr
         integer(c_int) :: status
      end function gsl_integration_qags
   end interface

end module wa_gsl
