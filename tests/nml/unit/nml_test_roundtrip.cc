// nml_test_roundtrip.cc: every message type through a real buffer (one process, two processes), corrupt messages, the codec table.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <set>

#include "nml_test.hh"

namespace {

// Read one message from `in` and compare it byte for byte with the expected fill.
bool read_and_compare(EmcChannel &in, NMLTYPE type, uint64_t seed)
{
    std::vector<unsigned char> want = test_filled_message(type, seed);
    const NMLmsg *got = in.read();
    if (!got) {
        printf("FAIL %s: nothing read (%s)\n", emc_symbol_lookup(type), in.error().c_str());
        return false;
    }
    if (got->type != type || got->size != want.size() || memcmp(got, want.data(), want.size())) {
        printf("FAIL %s: read back differs (type %d size %u)\n", emc_symbol_lookup(type),
               got->type, got->size);
        return false;
    }
    return true;
}

// Write every type's filled message to out; false at the first failure.
bool write_all(EmcChannel &out, uint64_t seed)
{
    for (NMLTYPE type : test_all_types()) {
        std::vector<unsigned char> msg = test_filled_message(type, seed + type);
        if (out.write(*reinterpret_cast<const NMLmsg *>(msg.data())) != 0) {
            printf("FAIL %s: write: %s\n", emc_symbol_lookup(type), out.error().c_str());
            return false;
        }
    }
    return true;
}

} // namespace

// One process: write each type, read it back at once.
void case_roundtrip()
{
    auto masters = test_create_all();
    auto out = test_open("bigq", "w1");
    auto in = test_open("bigq", "ro");
    int ok = 0;
    for (NMLTYPE type : test_all_types()) {
        std::vector<unsigned char> msg = test_filled_message(type, type);
        int rc = out->write(*reinterpret_cast<const NMLmsg *>(msg.data()));
        CHECK(rc == 0, "%s: write: %s", emc_symbol_lookup(type), out->error().c_str());
        ok += rc == 0 && read_and_compare(*in, type, type);
    }
    printf("roundtrip in one process: %d of %zu types intact\n", ok, test_all_types().size());
    CHECK(ok == static_cast<int>(test_all_types().size()), "some types failed");
}

// Two processes: a child writes every type, the parent reads and compares them.
void case_roundtrip_fork()
{
    auto masters = test_create_all();
    const uint64_t seed = 1000;
    pid_t pid = fork();
    if (pid == 0) {
        auto out = test_open("bigq", "w1");
        _exit(write_all(*out, seed) ? 0 : 1);
    }
    auto in = test_open("bigq", "ro");
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0, "writer process failed");
    int ok = 0;
    for (NMLTYPE type : test_all_types()) ok += read_and_compare(*in, type, seed + type);
    printf("roundtrip between two processes: %d of %zu types intact\n", ok,
           test_all_types().size());
    CHECK(ok == static_cast<int>(test_all_types().size()), "some types failed");
    CHECK(in->read() == nullptr && in->error().empty(), "queue not empty afterwards");
}

namespace {

// Write raw bytes through libnml (bypassing the checks), then read them through EmcChannel.
void expect_refused(nml_channel_t *raw, EmcChannel &in, const void *bytes, const char *label)
{
    int rc = nml_write(raw, bytes, nullptr);
    CHECK(rc == 0, "%s: raw write failed %d", label, rc);
    const NMLmsg *got = in.read();
    CHECK(got == nullptr, "%s: corrupt message was accepted", label);
    printf("%s: %s\n", label, in.error().c_str());
}

} // namespace

// Corrupt messages are refused by readers and by writers, with the reason.
void case_corrupt()
{
    auto masters = test_create_all();
    nml_channel_t *raw = test_open_raw("bigq", "w1");
    auto in = test_open("bigq", "ro");
    auto out = test_open("bigq", "w1");

    nml_msg_hdr_t unknown = {9999, sizeof(nml_msg_hdr_t), 0, 0};
    expect_refused(raw, *in, &unknown, "unknown type");

    unsigned char small[sizeof(EMC_TASK_SET_MODE) - 4] = {};
    nml_msg_hdr_t short_mode = {EMC_TASK_SET_MODE_TYPE, sizeof small, 0, 0};
    memcpy(small, &short_mode, sizeof short_mode);
    expect_refused(raw, *in, small, "short message");

    unsigned char big[64] = {};
    nml_msg_hdr_t long_mode = {EMC_TASK_SET_MODE_TYPE, sizeof big, 0, 0};
    memcpy(big, &long_mode, sizeof long_mode);
    expect_refused(raw, *in, big, "long message");

    EMC_TASK_PLAN_EXECUTE mdi;
    memset(mdi.command, 'G', sizeof mdi.command);
    expect_refused(raw, *in, &mdi, "unterminated text");

    EMC_STAT stat;
    memset(stat.task.file, 'x', sizeof stat.task.file);
    expect_refused(raw, *in, &stat, "unterminated status text");

    int rc = out->write(mdi);
    CHECK(rc == -EBADMSG, "writer accepted an unterminated text (%d)", rc);
    printf("writer: %s\n", out->error().c_str());
    EMC_TASK_SET_MODE mode;
    mode.size = 12;
    rc = out->write(mode);
    CHECK(rc == -EBADMSG, "writer accepted a bad size (%d)", rc);
    printf("writer: %s\n", out->error().c_str());
    CHECK(in->read() == nullptr && in->error().empty(), "refused messages reached the queue");

    EMC_TASK_SET_STATE state;
    out->write(state);
    EMC_STAT typed;
    rc = in->peek_as(typed);
    CHECK(rc == -EBADMSG, "peek_as accepted another class (%d)", rc);
    printf("peek_as: %s\n", in->error().c_str());
    nml_close(raw);
}

// The codec table: names without _TYPE, sizes, ascending numbers, LinuxCNC numbers.
void case_codec()
{
    std::vector<NMLTYPE> types = test_all_types();
    std::set<NMLTYPE> seen;
    for (size_t i = 0; i < types.size(); i++) {
        CHECK(i == 0 || types[i - 1] < types[i], "list not ascending at %d", types[i]);
        CHECK(seen.insert(types[i]).second, "type %d twice", types[i]);
        CHECK(emc_msg_known(types[i]) && emc_msg_size(types[i]) >= sizeof(NMLmsg),
              "type %d has no size", types[i]);
        CHECK(strstr(emc_symbol_lookup(types[i]), "_TYPE") == nullptr, "name with _TYPE");
    }
    printf("%zu message types\n", types.size());
    for (NMLTYPE t : {1, 11, 123, 204, 215, 505, 509, 1108, 1304, 1406, 1999})
        printf("%d %s\n", t, emc_symbol_lookup(t));
    printf("77 %s\n", emc_symbol_lookup(77));
    CHECK(emc_msg_max_size() == sizeof(EMC_STAT), "EMC_STAT is not the largest message");
    CHECK(sizeof(EMC_STAT) <= 20480, "EMC_STAT does not fit LinuxCNC's emcStatus size");
    CHECK(sizeof(EMC_TASK_PLAN_OPEN) + 16 <= 8192, "PLAN_OPEN does not fit emcCommand");
}
