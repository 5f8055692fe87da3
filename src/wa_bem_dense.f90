!> display: none
!>
!> Dense symmetric indefinite factorisation A = P L D L^T P^T with Bunch-Kaufman pivoting
!> (1x1 and 2x2 pivots; the algorithm of LAPACK's dsytf2/dsytrs, lower storage), its
!> solve, and the inertia of A from the pivots (Sylvester's law). Written here so that
!> the library needs no LAPACK; the trailing updates run down contiguous columns.
module wa_bem_dense
   use wa_kinds, only: wp
   implicit none
   private

   public :: ldl_type, ldl_factor, ldl_solve

   !> A factorisation: L and D packed in the lower triangle of a, pivots as in dsytrf.
   type :: ldl_type
      integer :: n = 0
      real(wp), allocatable :: a(:, :)
      integer, allocatable :: ipiv(:)
      !> Number of negative and zero eigenvalues of the factorised matrix
      integer :: negative = 0, zero = 0
   end type ldl_type

   !> Bunch-Kaufman's constant (1 + sqrt(17))/8: bounds the growth of L
   real(wp), parameter :: alpha_bk = 0.6403882032022076_wp

contains

   !> Factorise the symmetric matrix held in fact%a (lower triangle used) in place.
   pure subroutine ldl_factor(fact)
      type(ldl_type), intent(inout) :: fact
      integer :: n, k, kstep, kp, imax
      real(wp) :: absakk, colmax, rowmax

      n = size(fact%a, 1)
      fact%n = n
      if (allocated(fact%ipiv)) then
         if (size(fact%ipiv) /= n) deallocate (fact%ipiv)
      end if
      if (.not. allocated(fact%ipiv)) allocate (fact%ipiv(n))
      fact%negative = 0
      fact%zero = 0
      k = 1
      do while (k <= n)
         kstep = 1
         absakk = abs(fact%a(k, k))
         colmax = 0.0_wp
         imax = k
         if (k < n) then
            imax = k + maxloc(abs(fact%a(k + 1:n, k)), 1)
            colmax = abs(fact%a(imax, k))
         end if
         if (max(absakk, colmax) == 0.0_wp) then
            kp = k                       ! zero column: singular, nothing to eliminate
         else if (absakk >= alpha_bk*colmax) then
            kp = k
         else
            rowmax = 0.0_wp
            if (imax > k) rowmax = maxval(abs(fact%a(imax, k:imax - 1)))
            if (imax < n) rowmax = max(rowmax, maxval(abs(fact%a(imax + 1:n, imax))))
            if (absakk >= alpha_bk*colmax*(colmax/rowmax)) then
               kp = k
            else if (abs(fact%a(imax, imax)) >= alpha_bk*rowmax) then
               kp = imax
            else
               kp = imax
               kstep = 2
            end if
         end if
         call interchange(fact%a, k, k + kstep - 1, kp, kstep)
         if (kstep == 1) then
            fact%ipiv(k) = kp
            call eliminate_one(fact%a, k)
            if (fact%a(k, k) < 0.0_wp) fact%negative = fact%negative + 1
            if (fact%a(k, k) == 0.0_wp) fact%zero = fact%zero + 1
         else
            fact%ipiv(k) = -kp
            fact%ipiv(k + 1) = -kp
            call count_block(fact%a(k, k), fact%a(k + 1, k), fact%a(k + 1, k + 1), &
               fact%negative, fact%zero)
            call eliminate_two(fact%a, k)
         end if
         k = k + kstep
      end do
   end subroutine ldl_factor

   !> Swap rows and columns kk and kp of the trailing matrix (lower storage).
   pure subroutine interchange(a, k, kk, kp, kstep)
      real(wp), intent(inout) :: a(:, :)
      integer, intent(in) :: k, kk, kp, kstep
      integer :: n, j
      real(wp) :: t
      if (kp == kk) return
      n = size(a, 1)
      do j = kp + 1, n
         t = a(j, kk); a(j, kk) = a(j, kp); a(j, kp) = t
      end do
      do j = kk + 1, kp - 1
         t = a(j, kk); a(j, kk) = a(kp, j); a(kp, j) = t
      end do
      t = a(kk, kk); a(kk, kk) = a(kp, kp); a(kp, kp) = t
      if (kstep == 2) then
         t = a(k + 1, k); a(k + 1, k) = a(kp, k); a(kp, k) = t
      end if
   end subroutine interchange

   !> 1x1 pivot at k: rank-one update of the trailing lower triangle, column k scaled.
   pure subroutine eliminate_one(a, k)
      real(wp), intent(inout) :: a(:, :)
      integer, intent(in) :: k
      integer :: n, j
      real(wp) :: d11, c
      n = size(a, 1)
      if (a(k, k) == 0.0_wp) return
      d11 = 1.0_wp/a(k, k)
      do j = k + 1, n
         c = d11*a(j, k)
         if (c /= 0.0_wp) a(j:n, j) = a(j:n, j) - c*a(j:n, k)
      end do
      a(k + 1:n, k) = d11*a(k + 1:n, k)
   end subroutine eliminate_one

   !> 2x2 pivot at (k, k+1): rank-two update, columns k and k+1 replaced by L's.
   pure subroutine eliminate_two(a, k)
      real(wp), intent(inout) :: a(:, :)
      integer, intent(in) :: k
      integer :: n, j
      real(wp) :: d11, d22, d21, t, wk, wkp1
      n = size(a, 1)
      d21 = a(k + 1, k)
      d11 = a(k + 1, k + 1)/d21
      d22 = a(k, k)/d21
      t = 1.0_wp/(d11*d22 - 1.0_wp)
      d21 = t/d21
      do j = k + 2, n
         wk = d21*(d11*a(j, k) - a(j, k + 1))
         wkp1 = d21*(d22*a(j, k + 1) - a(j, k))
         a(j:n, j) = a(j:n, j) - a(j:n, k)*wk - a(j:n, k + 1)*wkp1
         a(j, k) = wk
         a(j, k + 1) = wkp1
      end do
   end subroutine eliminate_two

   !> Signs of the eigenvalues of the 2x2 pivot block [[a11, a21], [a21, a22]].
   pure subroutine count_block(a11, a21, a22, negative, zero)
      real(wp), intent(in) :: a11, a21, a22
      integer, intent(inout) :: negative, zero
      real(wp) :: det
      det = a11*a22 - a21*a21
      if (det < 0.0_wp) then
         negative = negative + 1
      else if (det == 0.0_wp) then
         zero = zero + 1
         if (a11 + a22 < 0.0_wp) negative = negative + 1
      else if (a11 + a22 < 0.0_wp) then
         negative = negative + 2
      end if
   end subroutine count_block

   !> Solve A x = b with the factorisation (b overwritten by x).
   pure subroutine ldl_solve(fact, b)
      type(ldl_type), intent(in) :: fact
      real(wp), intent(inout) :: b(:)
      integer :: n, k, kp
      real(wp) :: akm1k, akm1, ak, denom, bkm1, bk, t

      n = fact%n
      k = 1
      do while (k <= n)                    ! L D y = b
         if (fact%ipiv(k) > 0) then
            kp = fact%ipiv(k)
            if (kp /= k) then
               t = b(k); b(k) = b(kp); b(kp) = t
            end if
            if (k < n) b(k + 1:n) = b(k + 1:n) - fact%a(k + 1:n, k)*b(k)
            b(k) = b(k)/fact%a(k, k)
            k = k + 1
         else
            kp = -fact%ipiv(k)
            if (kp /= k + 1) then
               t = b(k + 1); b(k + 1) = b(kp); b(kp) = t
            end if
            if (k < n - 1) b(k + 2:n) = b(k + 2:n) - fact%a(k + 2:n, k)*b(k) &
               - fact%a(k + 2:n, k + 1)*b(k + 1)
            akm1k = fact%a(k + 1, k)
            akm1 = fact%a(k, k)/akm1k
            ak = fact%a(k + 1, k + 1)/akm1k
            denom = akm1*ak - 1.0_wp
            bkm1 = b(k)/akm1k
            bk = b(k + 1)/akm1k
            b(k) = (ak*bkm1 - bk)/denom
            b(k + 1) = (akm1*bk - bkm1)/denom
            k = k + 2
         end if
      end do
      k = n
      do while (k >= 1)                    ! L^T x = y
         if (fact%ipiv(k) > 0) then
            if (k < n) b(k) = b(k) - dot_product(fact%a(k + 1:n, k), b(k + 1:n))
            kp = fact%ipiv(k)
            if (kp /= k) then
               t = b(k); b(k) = b(kp); b(kp) = t
            end if
            k = k - 1
         else
            if (k < n) then
               b(k) = b(k) - dot_product(fact%a(k + 1:n, k), b(k + 1:n))
               b(k - 1) = b(k - 1) - dot_product(fact%a(k + 1:n, k - 1), b(k + 1:n))
            end if
            kp = -fact%ipiv(k)
            if (kp /= k) then
               t = b(k); b(k) = b(kp); b(kp) = t
            end if
            k = k - 2
         end if
      end do
   end subroutine ldl_solve

end module wa_bem_dense
