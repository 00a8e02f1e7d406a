#include <math.h>

#include "linear_solve.h"

int mlg_linear_solve(int n, double *A, double *b)
{
#define A_(i, j) A[(i) + n * (j)]
    for (int k = 0; k < n; k++) {
        int pivot = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(A_(i, k)) > fabs(A_(pivot, k))) pivot = i;
        if (A_(pivot, k) == 0.0) return -1;
        if (pivot != k) {
            for (int j = 0; j < n; j++) {
                double t = A_(k, j);
                A_(k, j) = A_(pivot, j);
                A_(pivot, j) = t;
            }
            double t = b[k];
            b[k] = b[pivot];
            b[pivot] = t;
        }
        for (int i = k + 1; i < n; i++) {
            double l = A_(i, k) / A_(k, k);
            for (int j = k; j < n; j++) A_(i, j) -= l * A_(k, j);
            b[i] -= l * b[k];
        }
    }
    for (int k = n - 1; k >= 0; k--) {
        for (int j = k + 1; j < n; j++) b[k] -= A_(k, j) * b[j];
        b[k] /= A_(k, k);
    }
    return 0;
#undef A_
}
