/* Linked into every AUTO equations executable by mk/auto.mk, with
 * -Wl,--wrap=_gfortran_set_options: AUTO's main program (lib/main.o, built
 * with AUTO) calls _gfortran_set_options(7, options) at start-up, and
 * options[6] is the -ffpe-summary= mask that libgfortran's STOP prints
 * ("Note: The following floating-point exceptions are signalling: ...").
 * The wrapper passes the same options with that mask 0, as if main.o had
 * been compiled with -ffpe-summary=none.  Floating-point behaviour is not
 * touched: no trap is set, no flag cleared; only the note at exit is gone.
 * Layout: libgfortran/runtime/compile_options.c (set_options), the same
 * from gfortran 4.9 to 14 (libgfortran.so.5). */
void __real__gfortran_set_options(int num, int options[]);
void __wrap__gfortran_set_options(int num, int options[]);

enum { FPE_SUMMARY = 6, MAX_OPTIONS = 64 };

void __wrap__gfortran_set_options(int num, int options[])
{
    int copy[MAX_OPTIONS];
    if (num <= FPE_SUMMARY || num > MAX_OPTIONS) {
        __real__gfortran_set_options(num, options);
        return;
    }
    for (int i = 0; i < num; i++) copy[i] = options[i];
    copy[FPE_SUMMARY] = 0;
    __real__gfortran_set_options(num, copy);
}
