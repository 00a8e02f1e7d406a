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
MLG_AVX2 ?= $(if $(filter x86_64-%,$(shell $(CC) -dumpmachine)),yes,no)
ifeq ($(MLG_AVX2),yes)
MLG_JACOBIAN_AVX2 := build/obj/vector_field_jacobian_avx2.o
$(MLG_JACOBIAN_AVX2): c/vector_field_jacobian.c $(MLG_HEADERS)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) -mavx2 -ffp-contract=off \
	    -DMLG_JACOBIAN_VARIANT=mlg_rhs_jacobian_avx2 -fPIC -c $< -o $@
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

$(MLG_TESTS): build/tests/%: tests/c/%.c tests/c/unit.h tests/c/near_equilibrium.h $(MLG_LIB) | $(PACKAGES_STAMP)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) -Itests/c $< $(MLG_LIB) -llapack -lm -o $@

TEST_DEPS += $(MLG_TESTS)

MLG_BENCH := build/bench/bench_vector_field
$(MLG_BENCH): tests/bench/bench_vector_field.c $(MLG_LIB)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $< $(MLG_LIB) -lm -o $@

BENCH_PROGRAMS += $(MLG_BENCH)

# Shared library for the Python drivers (mlgshimmy.shared.mlgmodel, via ctypes).
MLG_SHARED := build/lib/libmlg.so
$(MLG_SHARED): $(MLG_OBJECTS)
	@mkdir -p $(@D)
	$(CC) -shared $^ -lm -o $@
