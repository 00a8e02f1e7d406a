/* Dense linear solve by Gaussian elimination with partial pivoting. */
#ifndef MLG_LINEAR_SOLVE_H
#define MLG_LINEAR_SOLVE_H

/* Solves A x = b in place: A is n x n column-major (destroyed), b becomes x.
 * Returns 0, or -1 if A is singular to working precision. */
int mlg_linear_solve(int n, double *A, double *b);

#endif
