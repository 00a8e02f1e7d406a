/* mlg-shimmy version: the one place it is written.
 *
 * c/c.mk reads MLG_VERSION_MAJOR/MINOR/PATCH from here (the shared
 * library's file name libmlg.so.MAJOR.MINOR.PATCH, its SONAME libmlg.so.MAJOR
 * and the Version of mlg.pc); CITATION.cff repeats the version and
 * tests/release/test_c_library.py checks that the two agree.  MAJOR changes when the
 * library's interface changes incompatibly (a program built against the old
 * headers would misbehave with the new library), MINOR when it grows, PATCH
 * for fixes.  mlg_version() returns the version the library was built as,
 * for checking that header and library agree. */
#ifndef MLG_VERSION_H
#define MLG_VERSION_H

#define MLG_VERSION_MAJOR 0
#define MLG_VERSION_MINOR 1
#define MLG_VERSION_PATCH 0

#define MLG_VERSION_STRING_(a, b, c) #a "." #b "." #c
#define MLG_VERSION_STRING(a, b, c) MLG_VERSION_STRING_(a, b, c)
/* "MAJOR.MINOR.PATCH" */
#define MLG_VERSION MLG_VERSION_STRING(MLG_VERSION_MAJOR, MLG_VERSION_MINOR, MLG_VERSION_PATCH)
/* one number for comparisons: 10000 MAJOR + 100 MINOR + PATCH */
#define MLG_VERSION_NUMBER \
    (10000 * MLG_VERSION_MAJOR + 100 * MLG_VERSION_MINOR + MLG_VERSION_PATCH)

/* MLG_VERSION as the library was compiled (c/version.c) */
const char *mlg_version(void);

#endif
