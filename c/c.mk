# The model library (c/) and its C tests and benchmark; included by ../Makefile.
CC ?= gcc
# -fno-math-errno: the library never reads errno, and without it sqrt is a call
# (the errno path) and repeated sin/cos/acos of one argument are not shared;
# every result is the same to the bit either way.
MLG_CFLAGS := -std=c11 -O3 -fno-math-errno -Wall -Wextra -Wpedantic -Werror -Ic
MLG_LIB := build/lib/libmlg.a
MLG_SOURCES := $(wildcard c/*.c)
MLG_HEADERS := $(wildcard c/*.h)
MLG_OBJECTS := $(patsubst c/%.c,build/obj/%.o,$(MLG_SOURCES))

$(MLG_OBJECTS): build/obj/%.o: c/%.c $(MLG_HEADERS)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) -fPIC -c $< -o $@

# On x86-64 the Jacobian is built a second time for AVX2 (4-wide blocks, about
# 1.7 times faster), chosen at run time on CPUs that have it (jacobian_dispatch.c);
# -ffp-contract=off (as -std=c11 implies): no fused multiply-add, so that both
# builds round alike.  MLG_AVX2=no builds the generic one only.
MLG_AVX2 ?= $(if $(filter x86_64-%,$(shell $(call shell_quote,$(CC)) -dumpmachine)),yes,no)
MLG_AVX2_FLAGS := -mavx2 -ffp-contract=off -DMLG_JACOBIAN_VARIANT=mlg_rhs_jacobian_avx2
ifeq ($(MLG_AVX2),yes)
MLG_JACOBIAN_AVX2 := build/obj/vector_field_jacobian_avx2.o
$(MLG_JACOBIAN_AVX2): c/vector_field_jacobian.c $(MLG_HEADERS)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $(MLG_AVX2_FLAGS) -fPIC -c $< -o $@
MLG_OBJECTS += $(MLG_JACOBIAN_AVX2)
MLG_CFLAGS += -DMLG_HAVE_AVX2_VARIANT
endif

$(MLG_LIB): $(MLG_OBJECTS)
	@mkdir -p $(@D)
	rm -f $@
	ar rcs $@ $^

# C unit tests: tests/c/test_*.c, one executable each, linked with LAPACK.
MLG_TEST_SOURCES := $(wildcard tests/c/test_*.c)
MLG_TESTS := $(patsubst tests/c/%.c,build/tests/%,$(MLG_TEST_SOURCES))

$(MLG_TESTS): build/tests/%: tests/c/%.c tests/c/unit.h tests/c/near_equilibrium.h tests/c/state_samples.h tests/c/jacobian_error.h $(MLG_LIB) | $(PACKAGES_STAMP)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) -Itests/c $< $(MLG_LIB) -llapack -lm -o $@

TEST_DEPS += $(MLG_TESTS)

# The same tests once more with the library and the tests built under UBSan
# (undefined behaviour, and a double cast to an int it does not fit: not in
# -fsanitize=undefined): a report stops the program (tests/model/test_c_programs.py).
# -O1: a few seconds to build; the results are the same (no contraction either way).
MLG_UBSAN_FLAGS := -O1 -fsanitize=undefined,float-cast-overflow -fno-sanitize-recover=all
MLG_UBSAN_LIB := build/ubsan/lib/libmlg.a
MLG_UBSAN_OBJECTS := $(patsubst build/obj/%,build/ubsan/obj/%,$(MLG_OBJECTS))
MLG_UBSAN_TESTS := $(patsubst build/tests/%,build/ubsan/tests/%,$(MLG_TESTS))
build/ubsan/obj/%.o: c/%.c $(MLG_HEADERS)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $(MLG_UBSAN_FLAGS) -c $< -o $@
build/ubsan/obj/vector_field_jacobian_avx2.o: c/vector_field_jacobian.c $(MLG_HEADERS)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $(MLG_AVX2_FLAGS) $(MLG_UBSAN_FLAGS) -c $< -o $@
$(MLG_UBSAN_LIB): $(MLG_UBSAN_OBJECTS)
	@mkdir -p $(@D)
	rm -f $@
	ar rcs $@ $^
$(MLG_UBSAN_TESTS): build/ubsan/tests/%: tests/c/%.c tests/c/unit.h tests/c/near_equilibrium.h tests/c/state_samples.h tests/c/jacobian_error.h $(MLG_UBSAN_LIB) | $(PACKAGES_STAMP)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $(MLG_UBSAN_FLAGS) -Itests/c $< $(MLG_UBSAN_LIB) -llapack -lm -o $@

TEST_DEPS += $(MLG_UBSAN_TESTS)

MLG_BENCH := build/bench/bench_vector_field
$(MLG_BENCH): tests/bench/bench_vector_field.c $(MLG_LIB)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $< $(MLG_LIB) -lm -o $@

BENCH_PROGRAMS += $(MLG_BENCH)

# The version: c/mlg_version.h is its one source (MLG_VERSION_MAJOR/MINOR/PATCH).
mlg_version_part = $(shell sed -n 's/^.define MLG_VERSION_$(1)  *\([0-9][0-9]*\) *$$/\1/p' c/mlg_version.h)
MLG_VERSION_MAJOR := $(call mlg_version_part,MAJOR)
MLG_VERSION_MINOR := $(call mlg_version_part,MINOR)
MLG_VERSION_PATCH := $(call mlg_version_part,PATCH)
MLG_VERSION := $(MLG_VERSION_MAJOR).$(MLG_VERSION_MINOR).$(MLG_VERSION_PATCH)
ifneq ($(words $(MLG_VERSION_MAJOR) $(MLG_VERSION_MINOR) $(MLG_VERSION_PATCH)),3)
$(error c/mlg_version.h: cannot read MLG_VERSION_MAJOR/MINOR/PATCH (got '$(MLG_VERSION)'))
endif

# Shared library: the real file libmlg.so.MAJOR.MINOR.PATCH with the SONAME
# libmlg.so.MAJOR, and the symlinks libmlg.so.MAJOR and libmlg.so beside it;
# the Python drivers load build/lib/libmlg.so (mlgshimmy.shared.mlgmodel, ctypes).
MLG_SONAME := libmlg.so.$(MLG_VERSION_MAJOR)
MLG_SHARED_REAL := build/lib/libmlg.so.$(MLG_VERSION)
MLG_SHARED := build/lib/libmlg.so
$(MLG_SHARED_REAL): $(MLG_OBJECTS)
	@mkdir -p $(@D)
	$(CC) -shared -Wl,-soname,$(MLG_SONAME) $^ -lm -o $@
$(MLG_SHARED): $(MLG_SHARED_REAL)
	ln -sfn $(notdir $<) build/lib/$(MLG_SONAME)
	ln -sfn $(notdir $<) $@

# The public headers, installed as $(INCLUDEDIR)/mlg/; the rest of c/ is internal.
MLG_PUBLIC_HEADERS := c/mlg_model.h c/mlg_parameters.h c/mlg_version.h

# make install [PREFIX=/usr/local] [DESTDIR=<staging root>]: the headers in
# $(INCLUDEDIR)/mlg/, libmlg.so.$(MLG_VERSION) with its symlinks, libmlg.a
# and $(PKGCONFIGDIR)/mlg.pc (docs/c-library.md). make uninstall removes them.
PREFIX ?= /usr/local
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
# Checked before any rule runs, naming the variable: the directories are
# absolute without a ".." (so that everything lands inside $(DESTDIR)), and
# none of them nor DESTDIR holds a space (make splits on it: DESTDIR="x/with
# space" installed into x/with and ./space/) or a character the shell or sed
# would read.
MLG_INSTALL_DIRS := PREFIX LIBDIR INCLUDEDIR PKGCONFIGDIR
MLG_PATH_CHARS := a b c d e f g h i j k l m n o p q r s t u v w x y z \
    A B C D E F G H I J K L M N O P Q R S T U V W X Y Z 0 1 2 3 4 5 6 7 8 9 / . _ + -
mlg_strip = $(if $(2),$(call mlg_strip,$(subst $(firstword $(2)),,$(1)),$(wordlist 2,$(words $(2)),$(2))),$(1))
mlg_check_path = $(call refuse_space,$(1))$(if $(call mlg_strip,$($(1)),$(MLG_PATH_CHARS)),$(error \
    $(1)='$($(1))' holds a character other than letters, digits and / . _ + -; give a plain path))
ifneq ($(filter install uninstall,$(MAKECMDGOALS)),)
$(foreach v,DESTDIR $(MLG_INSTALL_DIRS),$(call mlg_check_path,$(v)))
$(foreach v,$(MLG_INSTALL_DIRS),$(if $(filter /%,$($(v))),,$(error $(v)='$($(v))' must be an \
    absolute path (e.g. /usr/local): the files go to $$(DESTDIR)$$($(v))))$(if \
    $(findstring /../,$($(v))/),$(error $(v)='$($(v))' has a ".." component: the files would \
    leave $$(DESTDIR))))
endif
# every file install writes, which uninstall removes
MLG_INSTALLED = $(addprefix $(INCLUDEDIR)/mlg/,$(notdir $(MLG_PUBLIC_HEADERS))) \
    $(addprefix $(LIBDIR)/,libmlg.so.$(MLG_VERSION) $(MLG_SONAME) libmlg.so libmlg.a) \
    $(PKGCONFIGDIR)/mlg.pc
.PHONY: install uninstall
install: $(MLG_LIB) $(MLG_SHARED_REAL) $(MLG_PUBLIC_HEADERS) c/mlg.pc.in
	install -d $(DESTDIR)$(INCLUDEDIR)/mlg $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR)
	install -m 644 $(MLG_PUBLIC_HEADERS) $(DESTDIR)$(INCLUDEDIR)/mlg/
	install -m 755 $(MLG_SHARED_REAL) $(DESTDIR)$(LIBDIR)/
	ln -sfn libmlg.so.$(MLG_VERSION) $(DESTDIR)$(LIBDIR)/$(MLG_SONAME)
	ln -sfn libmlg.so.$(MLG_VERSION) $(DESTDIR)$(LIBDIR)/libmlg.so
	install -m 644 $(MLG_LIB) $(DESTDIR)$(LIBDIR)/
	sed -e 's|@PREFIX@|$(PREFIX)|; s|@LIBDIR@|$(LIBDIR)|; s|@INCLUDEDIR@|$(INCLUDEDIR)|' \
	    -e 's|@VERSION@|$(MLG_VERSION)|' c/mlg.pc.in > $(DESTDIR)$(PKGCONFIGDIR)/mlg.pc
	@echo "install: mlg $(MLG_VERSION) under $(DESTDIR)$(PREFIX):" \
	    "headers $(INCLUDEDIR)/mlg/, libraries $(LIBDIR)/, pkg-config mlg"
uninstall:
	rm -f $(addprefix $(DESTDIR),$(MLG_INSTALLED))
	-rmdir $(DESTDIR)$(INCLUDEDIR)/mlg

# The example program (c/examples/evaluate.c), built here against the
# in-tree library so that `make test` keeps it compiling; tests/release/test_c_library.py
# builds it against an installed copy through pkg-config.
MLG_EXAMPLE := build/examples/evaluate
$(MLG_EXAMPLE): c/examples/evaluate.c $(MLG_PUBLIC_HEADERS) $(MLG_LIB)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $< $(MLG_LIB) -lm -o $@
TEST_DEPS += $(MLG_EXAMPLE)
