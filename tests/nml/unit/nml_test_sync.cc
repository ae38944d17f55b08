// nml_test_sync.cc: snapshots never torn under a 1 kHz writer, futex waits, master shutdown, tool data.
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "nml_test.hh"

namespace {

// A large status-like message with a checksum over everything after the header.
struct Snapshot {
    nml_msg_hdr_t head;
    uint64_t seq;
    uint64_t payload[2300];
    uint64_t checksum;
};
static_assert(sizeof(Snapshot) <= 20480, "snapshot must fit the stat buffer");

// FNV-1a over seq and payload.
uint64_t checksum_of(const Snapshot &s)
{
    uint64_t h = 1469598103934665603ULL;
    const unsigned char *p = reinterpret_cast<const unsigned char *>(&s.seq);
    size_t n = sizeof s.seq + sizeof s.payload;
    for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 1099511628211ULL;
    return h;
}

// Sleep until an absolute CLOCK_MONOTONIC time advanced by period_ns.
void sleep_until_next(struct timespec &t, long period_ns)
{
    t.tv_nsec += period_ns;
    while (t.tv_nsec >= 1000000000L) {
        t.tv_nsec -= 1000000000L;
        t.tv_sec++;
    }
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &t, nullptr);
}

// Child: write `count` snapshots at 1 kHz.
int snapshot_writer(int count)
{
    nml_channel_t *out = test_open_raw("stat", "w1");
    static Snapshot s;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    for (int i = 1; i <= count; i++) {
        s.head = {1, sizeof s, 0, 0};
        s.seq = static_cast<uint64_t>(i);
        uint64_t state = s.seq;
        for (uint64_t &w : s.payload) w = test_rand(state);
        s.checksum = checksum_of(s);
        if (nml_write(out, &s, nullptr) != 0) return 1;
        sleep_until_next(t, 1000000L);
    }
    nml_close(out);
    return 0;
}

} // namespace

// A reader hammering the status buffer never sees a torn snapshot.
void case_torn()
{
    auto masters = test_create_all();
    const int count = 1500;
    pid_t pid = fork();
    if (pid == 0) _exit(snapshot_writer(count));
    nml_channel_t *in = test_open_raw("stat", "ro");
    static Snapshot s;
    long reads = 0, torn = 0, distinct = 0;
    uint64_t last = 0;
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
        int n = nml_peek(in, &s, sizeof s);
        if (n <= 0) continue;
        reads++;
        if (n != static_cast<int>(sizeof s) || s.checksum != checksum_of(s)) torn++;
        if (s.seq != last) {
            torn += s.seq < last; // going backwards would be another kind of tear
            last = s.seq;
            distinct++;
        }
    }
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0, "writer failed");
    printf("torn snapshots: %ld\n", torn);
    printf("reader saw %s distinct snapshots and made %s reads\n",
           distinct >= 100 ? "at least 100" : "too few", reads > distinct ? "more" : "too few");
    CHECK(torn == 0 && distinct >= 100 && reads > distinct, "torn %ld distinct %ld reads %ld",
          torn, distinct, reads);
    fprintf(stderr, "torn test: %ld reads, %ld distinct of %d written\n", reads, distinct, count);
    nml_close(in);
}

// A sleeper in another process wakes on a write; a wait without a change times out.
void case_wait()
{
    auto masters = test_create_all();
    auto in = test_open("cmdq", "ro");
    uint32_t seen = in->change_count();
    int rc = in->wait_change(seen, 0.02);
    printf("wait without a change: %s\n", rc == -ETIMEDOUT ? "timed out" : "WRONG");
    CHECK(rc == -ETIMEDOUT, "rc %d", rc);
    pid_t pid = fork();
    if (pid == 0) {
        auto out = test_open("cmdq", "w1");
        usleep(50000);
        EMC_NULL m;
        _exit(out->write(m) == 0 ? 0 : 1);
    }
    rc = in->wait_change(seen, 10.0);
    const NMLmsg *m = in->read();
    printf("wait for a write from another process: %s\n",
           rc == 0 && m && m->type == EMC_NULL_TYPE ? "woke with the message" : "WRONG");
    CHECK(rc == 0 && m, "rc %d", rc);
    int status = 0;
    waitpid(pid, &status, 0);
}

// When the master closes, attached channels see the buffer gone.
void case_shutdown()
{
    auto master = test_open("stat", "svr");
    auto in = test_open("stat", "ro");
    uint32_t seen = in->change_count();
    CHECK(in->alive(), "not alive");
    master.reset();
    int rc = in->wait_change(seen, 1.0);
    const NMLmsg *m = in->peek();
    printf("after the master left: alive %d, wait %s, read: %s\n", in->alive(),
           rc == -ESHUTDOWN ? "-ESHUTDOWN" : "WRONG", in->error().c_str());
    CHECK(!in->alive() && rc == -ESHUTDOWN && !m, "still usable");
    std::string err;
    auto again = EmcChannel::open(test_nml_file(), "stat", "ro", &err);
    printf("reattach: %s\n", again ? "WRONG" : errno == ENOENT ? "refused, buffer does not exist" : err.c_str());
    CHECK(!again && errno == ENOENT, "reattached to a removed buffer");
}

// Tool data: publish, read back, find by number, generations, creator removes it.
void case_tooldata()
{
    char err[256];
    tooldata_t *missing = tooldata_open(0, err, sizeof err);
    printf("attach before creation: %s\n", missing ? "WRONG" : errno == ENOENT ? "refused, no segment" : err);
    tooldata_t *master = tooldata_open(1, err, sizeof err);
    tooldata_t *task = tooldata_open(0, err, sizeof err);
    tooldata_t *ui = tooldata_open(0, err, sizeof err);
    CHECK(master && task && ui, "open: %s", err);
    if (!master || !task || !ui) return;
    tooldata_entry_t table[4];
    for (int i = 0; i < 4; i++) {
        table[i] = tooldata_empty_entry();
        table[i].toolno = i ? 10 * i : -1;
        table[i].pocketno = i;
        table[i].offset.tran.z = 0.5 * i;
        snprintf(table[i].comment, sizeof table[i].comment, "tool %d", 10 * i);
    }
    uint64_t g0 = tooldata_generation(ui);
    CHECK(tooldata_publish(task, table, 4) == 0, "publish");
    tooldata_entry_t got[8];
    uint64_t gen = 0;
    int n = tooldata_read(ui, got, 8, &gen);
    CHECK(n == 4 && gen > g0 && !memcmp(got, table, sizeof table), "read back n=%d", n);
    tooldata_entry_t one;
    int idx = tooldata_find(ui, 20, &one);
    printf("tool 20 at index %d, z %.1f, comment '%s'\n", idx, one.offset.tran.z, one.comment);
    CHECK(idx == 2 && tooldata_find(ui, 99, nullptr) == -ENOENT, "find");
    table[1].diameter = 3.0;
    CHECK(tooldata_put(task, 6, &table[1]) == 0 && tooldata_read(ui, got, 8, nullptr) == 7,
          "put grows the table");
    CHECK(tooldata_get(ui, 5, &one) == 0 && one.toolno == -1 && tooldata_get(ui, 7, &one) == -ENOENT,
          "gap entries");
    CHECK(tooldata_publish(task, table, 0) == -EINVAL && tooldata_put(task, 5000, &one) == -EINVAL,
          "bad arguments accepted");
    printf("published %d entries, put grew it to 7, bad arguments refused\n", n);
    tooldata_close(ui);
    tooldata_close(task);
    tooldata_close(master);
    missing = tooldata_open(0, err, sizeof err);
    CHECK(!missing, "segment survived its creator");
}
