/* shm_unit.c: unit test of the motion segment: ring, NaN checks, seqlock, message queue, echo, client attach. */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "motion_client.h"

static int failures;

/* Report a failed expectation. */
#define EXPECT(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

/* A zeroed, initialised segment in ordinary memory. */
static emcmot_shm_t *new_segment(void)
{
    emcmot_shm_t *shm = aligned_alloc(EMCMOT_CACHE_LINE, sizeof *shm);
    emcmot_shm_init(shm, "unit", 1);
    return shm;
}

/* Fill the ring, overflow it, drain it: order, serials and contents survive. */
static void test_ring(void)
{
    emcmot_shm_t *shm = new_segment();
    emcmot_command_t cmd, out;
    long serial;

    for (int i = 0; i < EMCMOT_RING_CAPACITY; i++) {
        emcmot_command_init(&cmd, EMCMOT_SET_LINE);
        cmd.id = i;
        serial = emcmot_ring_push(shm, &cmd);
        EXPECT(serial == i + 1, "push %d gave serial %ld", i, serial);
    }
    emcmot_command_init(&cmd, EMCMOT_ABORT);
    EXPECT(emcmot_ring_push(shm, &cmd) == -EAGAIN, "full ring accepted a command");
    EXPECT(emcmot_ring_count(shm) == EMCMOT_RING_CAPACITY, "count %u", emcmot_ring_count(shm));
    for (int i = 0; i < EMCMOT_RING_CAPACITY; i++) {
        EXPECT(emcmot_ring_peek(shm, &out) == 1, "peek %d empty", i);
        EXPECT(out.id == i && out.serial == (uint32_t)i + 1 && out.command == EMCMOT_SET_LINE,
               "slot %d holds id %d serial %u", i, out.id, out.serial);
        emcmot_ring_pop(shm);
    }
    EXPECT(emcmot_ring_peek(shm, &out) == 0, "drained ring not empty");
    EXPECT(emcmot_ring_push(shm, &cmd) == EMCMOT_RING_CAPACITY + 1, "serial after drain");
    printf("ring: %d commands in order, full ring refused\n", EMCMOT_RING_CAPACITY);
    free(shm);
}

/* Every double of the command (and the tag's settings) is checked for NaN and inf. */
static void test_finite(void)
{
    emcmot_command_t cmd;
    const char *field = NULL;
    unsigned n = EMCMOT_COMMAND_DOUBLES, caught = 0;

    emcmot_command_init(&cmd, EMCMOT_SET_LINE);
    EXPECT(emcmot_command_check_finite(&cmd, &field) == 0, "clean command refused");
    for (unsigned i = 0; i < n; i++) {
        double *d = &cmd.pos.tran.x + i;
        *d = (i & 1) ? NAN : -INFINITY;
        if (emcmot_command_check_finite(&cmd, &field) == -EINVAL)
            caught++;
        else
            printf("double %u not checked\n", i);
        *d = 0.0;
    }
    cmd.tag.settings[1] = INFINITY;
    EXPECT(emcmot_command_check_finite(&cmd, &field) == -EINVAL && strcmp(field, "tag.settings[1]") == 0,
           "tag settings not checked");
    cmd.tag.settings[1] = 0;
    cmd.center.y = NAN;
    emcmot_command_check_finite(&cmd, &field);
    printf("finite: %u of %u doubles checked, center.y reported as '%s'\n", caught, n, field);
    EXPECT(caught == n, "unchecked doubles");
    EXPECT(emcmot_command_name(EMCMOT_SET_SPINDLE_PARAMS) != NULL &&
           strcmp(emcmot_command_name(74), "SET_SPINDLE_PARAMS") == 0, "name of 74");
    EXPECT(emcmot_command_name(0) == NULL && emcmot_command_name(75) == NULL, "unknown names");
    printf("names: 1=%s 20=%s 50=%s 74=%s\n", emcmot_command_name(1), emcmot_command_name(20),
           emcmot_command_name(50), emcmot_command_name(74));
}

typedef struct seq_ctx {
    emcmot_shm_t *shm;
    volatile int stop;
    long torn;
    long reads;
} seq_ctx_t;

/* Writer thread: every published status has heartbeat == a few fields far apart. */
static void *seq_writer(void *arg)
{
    seq_ctx_t *ctx = arg;
    static emcmot_status_t st;

    for (uint32_t beat = 1; !ctx->stop; beat++) {
        st.heartbeat = beat;
        st.cycle_time = beat;
        st.joint[EMCMOT_MAX_JOINTS - 1].pos_cmd = beat;
        st.spindle[EMCMOT_MAX_SPINDLES - 1].speed = beat;
        emcmot_status_publish(ctx->shm, &st);
    }
    return NULL;
}

/* Readers see whole snapshots while a writer publishes flat out. */
static void test_seqlock(void)
{
    seq_ctx_t ctx = { new_segment(), 0, 0, 0 };
    static emcmot_status_t st;
    pthread_t writer;

    pthread_create(&writer, NULL, seq_writer, &ctx);
    for (int i = 0; i < 200000; i++) {
        if (emcmot_status_read(ctx.shm, &st, 100000) < 0)
            continue;
        ctx.reads++;
        double b = st.heartbeat;
        if (st.cycle_time != b || st.joint[EMCMOT_MAX_JOINTS - 1].pos_cmd != b ||
            st.spindle[EMCMOT_MAX_SPINDLES - 1].speed != b)
            ctx.torn++;
    }
    ctx.stop = 1;
    pthread_join(writer, NULL);
    EXPECT(ctx.torn == 0, "%ld torn snapshots", ctx.torn);
    EXPECT(ctx.reads > 0, "no read succeeded");
    printf("seqlock: no torn snapshot\n");
    free(ctx.shm);
}

typedef struct msg_ctx {
    emcmot_shm_t *shm;
    int base;
} msg_ctx_t;

/* Producer thread for the message queue: 1000 numbered messages, retried while full. */
static void *msg_writer(void *arg)
{
    msg_ctx_t *ctx = arg;
    char text[32];

    for (int i = 0; i < 1000; i++) {
        snprintf(text, sizeof text, "%d", ctx->base + i);
        while (emcmot_error_push(ctx->shm, EMCMOT_MSG_ERROR, text) < 0)
            ;
    }
    return NULL;
}

/* Message queue: bounded, FIFO, truncating, safe with two writers. */
static void test_messages(void)
{
    emcmot_shm_t *shm = new_segment();
    char buf[EMCMOT_ERROR_LEN], big[3000];
    int kind, last[2] = { -1, 999 }, got = 0;
    pthread_t w[2];
    msg_ctx_t ctx[2] = { { shm, 0 }, { shm, 1000 } };

    for (int i = 0; i < EMCMOT_ERROR_SLOTS; i++)
        EXPECT(emcmot_error_push(shm, EMCMOT_MSG_TEXT, "m") == 0, "push %d", i);
    EXPECT(emcmot_error_push(shm, EMCMOT_MSG_ERROR, "lost") == -ENOSPC, "full queue accepted");
    EXPECT(shm->errors.dropped == 1, "dropped %u", shm->errors.dropped);
    while (emcmot_error_pop(shm, &kind, buf, sizeof buf) == 1)
        got++;
    EXPECT(got == EMCMOT_ERROR_SLOTS && kind == EMCMOT_MSG_TEXT, "popped %d", got);
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    emcmot_error_push(shm, EMCMOT_MSG_ERROR, big);
    emcmot_error_pop(shm, &kind, buf, sizeof buf);
    EXPECT(strlen(buf) == EMCMOT_ERROR_LEN - 1, "long message length %zu", strlen(buf));
    pthread_create(&w[0], NULL, msg_writer, &ctx[0]);
    pthread_create(&w[1], NULL, msg_writer, &ctx[1]);
    for (got = 0; got < 2000;) {
        if (emcmot_error_pop(shm, &kind, buf, sizeof buf) != 1)
            continue;
        int v = atoi(buf), who = v >= 1000;
        EXPECT(v == last[who] + 1, "writer %d: %d after %d", who, v, last[who]);
        last[who] = v;
        got++;
    }
    pthread_join(w[0], NULL);
    pthread_join(w[1], NULL);
    printf("messages: bounded, truncated at %d, 2 writers x 1000 in order\n", EMCMOT_ERROR_LEN - 1);
    free(shm);
}

/* The echo lookup finds rejections, reports OK otherwise, and knows when it forgot. */
static void test_echo(void)
{
    emcmot_echo_t echo;
    int result = -1;
    char reason[64];

    memset(&echo, 0, sizeof echo);
    EXPECT(emcmot_echo_lookup(&echo, 1, &result, reason, sizeof reason) == 0, "nothing handled");
    echo.serial = 10;
    echo.handled = 10;
    echo.rejected = 1;
    echo.reject[0] = (emcmot_reject_t){ 7, EMCMOT_JOG_CONT, EMCMOT_COMMAND_INVALID_COMMAND, 1,
                                        "Can't jog joint when not enabled." };
    EXPECT(emcmot_echo_lookup(&echo, 11, &result, reason, sizeof reason) == 0, "11 not yet");
    EXPECT(emcmot_echo_lookup(&echo, 7, &result, reason, sizeof reason) == 1 &&
           result == EMCMOT_COMMAND_INVALID_COMMAND, "7 rejected");
    printf("echo: 7 -> %s '%s'\n", emcmot_result_name(result), reason);
    EXPECT(emcmot_echo_lookup(&echo, 8, &result, reason, sizeof reason) == 1 &&
           result == EMCMOT_COMMAND_OK, "8 ok");
    echo.rejected = EMCMOT_REJECT_HISTORY + 3;
    for (int i = 0; i < EMCMOT_REJECT_HISTORY; i++)
        echo.reject[i].serial = 100 + i;
    echo.serial = 200;
    EXPECT(emcmot_echo_lookup(&echo, 50, &result, reason, sizeof reason) == -ENODATA, "forgotten");
    EXPECT(emcmot_echo_lookup(&echo, 150, &result, reason, sizeof reason) == 1 &&
           result == EMCMOT_COMMAND_OK, "150 ok");
}

/* Through SysV: owner creates, one producer only, a reader sees the header. */
static void test_client(void)
{
    emcmot_client_t *owner, *producer, *second, *reader;
    char why[200];
    emcmot_command_t cmd, out;

    EXPECT(emcmot_attach(4242, EMCMOT_ATTACH_READER, &reader, why, sizeof why) == -ENOENT,
           "attached to a missing segment");
    printf("attach without owner: %s\n", strstr(why, "not found") ? strstr(why, "not found") : why);
    EXPECT(emcmot_create(4242, "unit", &owner, why, sizeof why) == 0, "create: %s", why);
    EXPECT(emcmot_attach(4242, EMCMOT_ATTACH_PRODUCER, &producer, why, sizeof why) == 0,
           "attach: %s", why);
    emcmot_shm_t *shm = emcmot_client_shm(owner);
    shm->header.producer_pid = 1;       /* pid 1 is alive: a foreign producer */
    EXPECT(emcmot_attach(4242, EMCMOT_ATTACH_PRODUCER, &second, why, sizeof why) == -EBUSY,
           "second producer accepted");
    printf("second producer: %s\n", why);
    shm->header.producer_pid = (int32_t)getpid();
    emcmot_command_init(&cmd, EMCMOT_ENABLE);
    EXPECT(emcmot_attach(4242, EMCMOT_ATTACH_READER, &reader, why, sizeof why) == 0, "reader");
    EXPECT(emcmot_push(reader, &cmd) == -EPERM, "reader pushed");
    EXPECT(emcmot_push(producer, &cmd) == 1, "producer push");
    EXPECT(emcmot_ring_peek(shm, &out) == 1 && out.command == EMCMOT_ENABLE, "command not in ring");
    emcmot_detach(owner);
    EXPECT(emcmot_push(producer, &cmd) == -EPIPE, "push after the owner left");
    emcmot_detach(producer);
    emcmot_detach(reader);
    EXPECT(emcmot_attach(4242, EMCMOT_ATTACH_READER, &reader, why, sizeof why) == -ENOENT,
           "segment left behind");
}

int main(void)
{
    test_ring();
    test_finite();
    test_seqlock();
    test_messages();
    test_echo();
    test_client();
    printf("%s\n", failures ? "FAILED" : "all passed");
    return failures ? 1 : 0;
}
