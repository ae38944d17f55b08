// nml_test_queue.cc: full queues, wrap-around order, confirm_write, and one serial sequence shared by all writers.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <deque>

#include "nml_test.hh"

// Fill the command queue until it refuses; nothing queued is lost or reordered.
void case_queue_full()
{
    auto masters = test_create_all();
    auto out = test_open("cmdq", "w1");
    auto in = test_open("cmdq", "ro");
    EMC_TASK_SET_MODE mode;
    int written = 0, rc;
    int32_t serial = 0;
    for (;;) {
        mode.mode = written + 1;
        rc = out->write(mode, &serial);
        if (rc != 0) break;
        written++;
    }
    printf("queue took %d messages, then: %s\n", written, out->error().c_str());
    CHECK(rc == -EAGAIN, "full queue gave %d", rc);
    CHECK(in->queue_count() == written, "queue_count %d", in->queue_count());
    CHECK(out->write_count() == static_cast<uint64_t>(written), "a refused write used a serial");
    int order_ok = 1;
    for (int i = 1; i <= written; i++) {
        const EMC_TASK_SET_MODE *m = emc_msg_as<EMC_TASK_SET_MODE>(in->read());
        order_ok &= m && m->mode == i && m->serial_number == i;
    }
    CHECK(order_ok, "messages lost or reordered");
    CHECK(in->read() == nullptr, "more messages than written");
    rc = out->write(mode, &serial);
    CHECK(rc == 0 && serial == written + 1, "write after draining: rc %d serial %d", rc, serial);
    printf("read back %d in order, next serial %d\n", written, serial);
}

namespace {

// One random message for the wrap test: its type and a marker in a field.
struct Sent {
    NMLTYPE type;
    int32_t marker;
};

// Write a message of the chosen kind carrying marker; the write's return code.
int write_kind(EmcChannel &out, int kind, int32_t marker)
{
    if (kind == 0) {
        EMC_TASK_SET_MODE m;
        m.mode = marker;
        return out.write(m);
    }
    if (kind == 1) {
        EMC_OPERATOR_TEXT m;
        snprintf(m.text, sizeof m.text, "%d", marker);
        return out.write(m);
    }
    EMC_TASK_PLAN_OPEN m;
    m.remote_filesize = marker;
    return out.write(m);
}

// Marker of a read message, or -1.
int32_t marker_of(const NMLmsg *m)
{
    if (auto *a = emc_msg_as<EMC_TASK_SET_MODE>(m)) return a->mode;
    if (auto *b = emc_msg_as<EMC_OPERATOR_TEXT>(m)) return atoi(b->text);
    if (auto *c = emc_msg_as<EMC_TASK_PLAN_OPEN>(m)) return c->remote_filesize;
    return -1;
}

} // namespace

// Mixed sizes, random reads and writes: the queue behaves like a FIFO through many wraps.
void case_queue_wrap()
{
    auto masters = test_create_all();
    auto out = test_open("cmdq", "w1");
    auto in = test_open("cmdq", "ro");
    std::deque<Sent> model;
    uint64_t state = 42;
    int writes = 0, fulls = 0, reads = 0, bad = 0;
    for (int32_t step = 0; step < 20000; step++) {
        if (test_rand(state) % 100 < 55) {
            int kind = static_cast<int>(test_rand(state) % 3);
            int rc = write_kind(*out, kind, step);
            if (rc == 0) {
                model.push_back({kind == 0 ? EMC_TASK_SET_MODE_TYPE : kind == 1 ? EMC_OPERATOR_TEXT_TYPE
                                                                                : EMC_TASK_PLAN_OPEN_TYPE,
                                 step});
                writes++;
            } else {
                bad += rc != -EAGAIN;
                fulls++;
            }
        } else {
            const NMLmsg *m = in->read();
            if (model.empty()) {
                bad += m != nullptr;
                continue;
            }
            bad += !m || m->type != model.front().type || marker_of(m) != model.front().marker;
            model.pop_front();
            reads++;
        }
        bad += in->queue_count() != static_cast<int>(model.size());
    }
    printf("wrap: %s (%s)\n", bad == 0 ? "queue matched the FIFO model" : "MISMATCH",
           writes > 1000 && fulls > 100 && reads > 1000 ? "many writes, reads and full refusals"
                                                        : "too few operations");
    CHECK(bad == 0, "%d mismatches", bad);
}

// Records that fill the ring exactly: after the reader has consumed up to its very end, with the
// oldest record back at its start, the ring takes exactly as many records as were read, in order.
void case_queue_end()
{
    auto masters = test_create_all();
    auto out = test_open("cmdq", "w1");
    auto in = test_open("cmdq", "ro");
    int marker = 0, next = 0, bad = 0;
    auto put = [&]() {
        EMC_JOG_INCR m;
        m.jjogmode = marker;
        int rc = out->write(m);
        marker += rc == 0;
        return rc;
    };
    auto take = [&]() {
        const EMC_JOG_INCR *m = emc_msg_as<EMC_JOG_INCR>(in->read());
        bad += !m || m->jjogmode != next++;
    };
    int full = 0;
    while (put() == 0) full++;
    take();
    bad += put() != 0;                  /* into the record freed at the start */
    for (int k = 0; k < full - 1; k++) take();
    int again = 0;
    while (again <= full && put() == 0) again++;   /* bounded: a ring that overwrites never fills */
    while (in->queue_count() > 0) take();
    printf("queue end: %d records fill the ring; with the oldest at its start it took %d more, "
           "%s\n", full, again, bad ? "OUT OF ORDER" : "read back in order");
    CHECK(again == full - 1 && bad == 0, "took %d, %d mismatches", again, bad);
}

// A confirm_write latest-value buffer refuses a write until the last message was read.
void case_confirm_write()
{
    auto masters = test_create_all();
    auto out = test_open("confirm", "w1");
    auto in = test_open("confirm", "ro");
    EMC_TASK_SET_MODE m;
    int first = out->write(m);
    int second = out->write(m);
    printf("confirm_write: second write before a read: %s\n", out->error().c_str());
    in->peek();
    int after_peek = out->write(m);
    in->read();
    int after_read = out->write(m);
    CHECK(first == 0 && second == -EBUSY && after_peek == -EBUSY && after_read == 0,
          "rc %d %d %d %d", first, second, after_peek, after_read);
    printf("confirm_write: a peek does not confirm, a read does\n");
}

// Two writers alternating in one process get one consecutive sequence.
void case_serial_shared()
{
    auto masters = test_create_all();
    auto a = test_open("cmdq", "w1");
    auto b = test_open("cmdq", "w2");
    EMC_NULL m;
    int32_t s[4] = {};
    a->write(m, &s[0]);
    b->write(m, &s[1]);
    a->write(m, &s[2]);
    b->write(m, &s[3]);
    printf("alternating writers got serials %d %d %d %d\n", s[0], s[1], s[2], s[3]);
    CHECK(s[0] == 1 && s[1] == 2 && s[2] == 3 && s[3] == 4, "not one sequence");
}

namespace {

const int PER_WRITER = 2000;

// Child: write PER_WRITER messages tagged with its id; retry while the queue is full.
int writer_process(const char *process, int id)
{
    auto out = test_open("cmdq", process);
    int32_t last = 0;
    for (int i = 0; i < PER_WRITER; i++) {
        EMC_JOG_INCR m;
        m.joint_or_axis = id;
        m.jjogmode = i;
        int32_t serial = 0;
        int rc;
        while ((rc = out->write(m, &serial)) == -EAGAIN) out->wait_change(out->change_count(), 0.01);
        if (rc != 0 || serial <= last) return 1;
        last = serial;
    }
    return 0;
}

} // namespace

// Two writer processes and a reader: serials 1..2N, each once, in queue order.
void case_serial_fork()
{
    auto masters = test_create_all();
    auto in = test_open("cmdq", "ro");
    pid_t pids[2];
    for (int id = 0; id < 2; id++) {
        pids[id] = fork();
        if (pids[id] == 0) _exit(writer_process(id ? "w2" : "w1", id));
    }
    int expected_serial = 1, next_local[2] = {0, 0}, bad = 0;
    while (expected_serial <= 2 * PER_WRITER) {
        uint32_t seen = in->change_count();
        const NMLmsg *msg = in->read();
        if (!msg) {
            if (in->wait_change(seen, 5.0) == -ETIMEDOUT) break;
            continue;
        }
        const EMC_JOG_INCR *m = emc_msg_as<EMC_JOG_INCR>(msg);
        bad += !m || m->serial_number != expected_serial || m->joint_or_axis < 0 ||
               m->joint_or_axis > 1 || m->jjogmode != next_local[m->joint_or_axis]++;
        expected_serial++;
    }
    for (pid_t pid : pids) {
        int status = 0;
        waitpid(pid, &status, 0);
        bad += !WIFEXITED(status) || WEXITSTATUS(status) != 0;
    }
    printf("two writer processes: %d messages, serials %s\n", expected_serial - 1,
           bad ? "WRONG" : "1..N each once, in order, each writer's own order kept");
    CHECK(bad == 0 && expected_serial == 2 * PER_WRITER + 1, "%d problems", bad);
}
