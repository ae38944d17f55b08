// nml_test_main.cc: the libnml/EMC message test program: `nml_test CASE...` runs the named cases.
#include <cstdlib>
#include <cstring>
#include <unistd.h>

#include "nml_test.hh"

int test_failures = 0;

// Test file path.
std::string test_nml_file()
{
    const char *env = getenv("NML_TEST_FILE");
    if (env && *env) return env;
    const char *home = getenv("EMC2_HOME");
    return std::string(home ? home : ".") + "/tests/nml/unit/test.nml";
}

// Open or abort.
std::unique_ptr<EmcChannel> test_open(const char *buffer, const char *process)
{
    std::string err;
    auto ch = EmcChannel::open(test_nml_file(), buffer, process, &err);
    if (!ch) {
        printf("FAIL: cannot open %s as %s: %s\n", buffer, process, err.c_str());
        exit(1);
    }
    return ch;
}

// Open raw or abort.
nml_channel_t *test_open_raw(const char *buffer, const char *process)
{
    char err[512];
    nml_channel_t *ch = nml_open(test_nml_file().c_str(), buffer, process, err, sizeof err);
    if (!ch) {
        printf("FAIL: cannot open %s as %s: %s\n", buffer, process, err);
        exit(1);
    }
    return ch;
}

// Masters of all buffers.
std::vector<std::unique_ptr<EmcChannel>> test_create_all()
{
    std::vector<std::unique_ptr<EmcChannel>> all;
    for (const char *name : {"cmdq", "stat", "bigq", "confirm"}) all.push_back(test_open(name, "svr"));
    return all;
}

// xorshift64*.
uint64_t test_rand(uint64_t &state)
{
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 2685821657736338717ULL;
}

// A filled message of a type.
std::vector<unsigned char> test_filled_message(NMLTYPE type, uint64_t seed)
{
    size_t size = emc_msg_size(type);
    std::vector<unsigned char> bytes(size);
    uint64_t state = seed * 0x9E3779B97F4A7C15ULL + 1;
    for (size_t i = sizeof(nml_msg_hdr_t); i < size; i++)
        bytes[i] = (i % 64 == 63) ? 0 : static_cast<unsigned char>(1 + test_rand(state) % 255);
    nml_msg_hdr_t head = {type, static_cast<uint32_t>(size), 0, 0};
    memcpy(bytes.data(), &head, sizeof head);
    return bytes;
}

// All listed types.
std::vector<NMLTYPE> test_all_types()
{
    std::vector<NMLTYPE> types;
#define ADD_TYPE(name, number) types.push_back(number);
    EMC_MSG_LIST(ADD_TYPE)
#undef ADD_TYPE
    return types;
}

namespace {

struct Case {
    const char *name;
    void (*run)();
};

const Case cases[] = {
    {"roundtrip", case_roundtrip},       {"roundtrip-fork", case_roundtrip_fork},
    {"corrupt", case_corrupt},           {"queue-full", case_queue_full},
    {"queue-wrap", case_queue_wrap},     {"queue-end", case_queue_end},     {"confirm-write", case_confirm_write},
    {"serial-shared", case_serial_shared}, {"serial-fork", case_serial_fork},
    {"torn", case_torn},                 {"wait", case_wait},
    {"shutdown", case_shutdown},         {"codec", case_codec},
    {"tooldata", case_tooldata},
};

} // namespace

int main(int argc, char **argv)
{
    setvbuf(stdout, nullptr, _IOLBF, 0);
    if (argc < 2) {
        fprintf(stderr, "usage: nml_test CASE...\n");
        return 2;
    }
    for (int i = 1; i < argc; i++) {
        const Case *found = nullptr;
        for (const Case &c : cases)
            if (!strcmp(c.name, argv[i])) found = &c;
        if (!found) {
            fprintf(stderr, "nml_test: unknown case '%s'\n", argv[i]);
            return 2;
        }
        found->run();
    }
    return test_failures ? 1 : 0;
}
