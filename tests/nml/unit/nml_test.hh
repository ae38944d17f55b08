// nml_test.hh: helpers shared by the libnml test program's cases (tests/nml/unit).
#ifndef NML_TEST_HH
#define NML_TEST_HH

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "emc_nml.hh"

// Failed checks so far; main() exits 1 when any.
extern int test_failures;

// Report a failed check (file:line: text) and count it.
#define CHECK(cond, ...)                                              \
    do {                                                              \
        if (!(cond)) {                                                \
            fprintf(stdout, "FAIL %s:%d: ", __FILE__, __LINE__);     \
            fprintf(stdout, __VA_ARGS__);                             \
            fputc('\n', stdout);                                      \
            test_failures++;                                          \
        }                                                             \
    } while (0)

// Path of tests/nml/unit/test.nml (from $NML_TEST_FILE or next to the binary's tree).
std::string test_nml_file();
// Open a buffer of test.nml as a process; aborts the test when it fails.
std::unique_ptr<EmcChannel> test_open(const char *buffer, const char *process);
// Raw libnml channel of test.nml; aborts when it fails.
nml_channel_t *test_open_raw(const char *buffer, const char *process);
// Master channels of every buffer of test.nml (creates them).
std::vector<std::unique_ptr<EmcChannel>> test_create_all();

// Deterministic pseudo-random numbers.
uint64_t test_rand(uint64_t &state);
// A message of type number `type` filled from seed: header intact, every other byte
// pseudo-random, with a NUL every 64 bytes so text fields are always terminated.
std::vector<unsigned char> test_filled_message(NMLTYPE type, uint64_t seed);
// Every type of EMC_MSG_LIST.
std::vector<NMLTYPE> test_all_types();

// Cases (each prints its results).
void case_roundtrip();
void case_roundtrip_fork();
void case_corrupt();
void case_queue_full();
void case_queue_wrap();
void case_queue_end();
void case_confirm_write();
void case_serial_shared();
void case_serial_fork();
void case_torn();
void case_wait();
void case_shutdown();
void case_codec();
void case_tooldata();

#endif
