#ifndef hrcontact_blas_lapack_h
#define hrcontact_blas_lapack_h

/**
 * The reference BLAS and LAPACK routines the code calls directly
 * (column-major, Fortran names), linked through deal.II: where a dense
 * kernel must be one call on raw arrays (the equilibrium reduction, the
 * error bound's local problems) rather than through LAPACKFullMatrix.
 */
extern "C"
{
  void
  dgetrf_(const int *m,
          const int *n,
          double    *a,
          const int *lda,
          int       *ipiv,
          int       *info);
  void
  dtrsm_(const char   *side,
         const char   *uplo,
         const char   *transa,
         const char   *diag,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         double       *b,
         const int    *ldb);
  void
  dtrsv_(const char   *uplo,
         const char   *trans,
         const char   *diag,
         const int    *n,
         const double *a,
         const int    *lda,
         double       *x,
         const int    *incx);
  void
  dgemm_(const char   *transa,
         const char   *transb,
         const int    *m,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *b,
         const int    *ldb,
         const double *beta,
         double       *c,
         const int    *ldc);
  void
  dgemv_(const char   *trans,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *x,
         const int    *incx,
         const double *beta,
         double       *y,
         const int    *incy);
  void
  dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);
  void
  dtrmv_(const char   *uplo,
         const char   *trans,
         const char   *diag,
         const int    *n,
         const double *a,
         const int    *lda,
         double       *x,
         const int    *incx);
  void
  dpotrs_(const char   *uplo,
          const int    *n,
          const int    *nrhs,
          const double *a,
          const int    *lda,
          double       *b,
          const int    *ldb,
          int          *info);
  void
  dgeqp3_(const int *m,
          const int *n,
          double    *a,
          const int *lda,
          int       *jpvt,
          double    *tau,
          double    *work,
          const int *lwork,
          int       *info);
  void
  dormqr_(const char   *side,
          const char   *trans,
          const int    *m,
          const int    *n,
          const int    *k,
          const double *a,
          const int    *lda,
          const double *tau,
          double       *c,
          const int    *ldc,
          double       *work,
          const int    *lwork,
          int          *info);
  void
  dorgqr_(const int    *m,
          const int    *n,
          const int    *k,
          double       *a,
          const int    *lda,
          const double *tau,
          double       *work,
          const int    *lwork,
          int          *info);
}

#endif
