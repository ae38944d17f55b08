/* hal_core_api.c: unit test of the HAL library's user-side API (comps, pins, params, signals, locks, aliases, ports, malloc, ids). */
#include "hal.h"
#include "hal_priv.h"
#include <stdio.h>
#include <string.h>
#include <errno.h>

/* Print one call's result with its hal_strerror text. */
static void show(const char *what, int rc)
{
    printf("%-44s %d%s%s\n", what, rc, rc < 0 ? " " : "", rc < 0 ? hal_strerror(rc) : "");
}

/* Print the current value of a pin/param/signal as the test expects it. */
static void value(const char *name, int is_sig)
{
    hal_type_t type;
    hal_data_u v;
    int dir, rc = is_sig ? hal_get_s(name, &type, &v, NULL) : hal_get_p(name, &type, &dir, &v);

    if (rc < 0) {
        printf("value %s: %s\n", name, hal_strerror(rc));
        return;
    }
    switch (type) {
    case HAL_BIT: printf("value %s = %s\n", name, v.b ? "TRUE" : "FALSE"); break;
    case HAL_FLOAT: printf("value %s = %g\n", name, v.f); break;
    case HAL_S32: printf("value %s = %d\n", name, v.s); break;
    case HAL_U32: printf("value %s = %u\n", name, v.u); break;
    case HAL_S64: printf("value %s = %lld\n", name, (long long)v.ls); break;
    case HAL_U64: printf("value %s = %llu\n", name, (unsigned long long)v.lu); break;
    default: printf("value %s = port %u\n", name, v.u); break;
    }
}

/* Print all pins in list order with owner, dir and signal. */
static void list_pins(void)
{
    hal_pin_t *p;
    halpr_mutex_get();
    for (p = halpr_first_pin(); p; p = halpr_next_pin(p))
        printf("pin %s owner=%s dir=%d sig=%s%s%s\n", p->name, halpr_owner(p->owner_ptr)->name,
               p->dir, p->signal ? ((hal_sig_t *)SHMPTR(p->signal))->name : "-",
               p->oldname ? " orig=" : "", p->oldname ? halpr_original_name(p->oldname) : "");
    halpr_mutex_give();
}

/* Print signals with their counters and linked pins. */
static void list_sigs(void)
{
    hal_sig_t *s;
    hal_pin_t *p;
    halpr_mutex_get();
    for (s = halpr_first_sig(); s; s = halpr_next_sig(s)) {
        printf("sig %s type=%d r=%d w=%d b=%d:", s->name, s->type, s->readers, s->writers, s->bidirs);
        for (p = halpr_first_sig_pin(s); p; p = halpr_next_sig_pin(p))
            printf(" %s", p->name);
        printf("\n");
    }
    halpr_mutex_give();
}

/* Print components newest first. */
static void list_comps(void)
{
    hal_comp_t *c;
    halpr_mutex_get();
    for (c = halpr_first_comp(); c; c = halpr_next_comp(c))
        printf("comp %d %s type=%d ready=%d pid=%s\n", c->comp_id, c->name, c->type, c->ready,
               c->pid > 0 ? "yes" : "no");
    halpr_mutex_give();
}

/* A function that user comps may not export. */
static void nop_funct(void *arg, long period)
{
    (void)arg;
    (void)period;
}

struct pins {
    hal_bit_t *bin, *bout, *bio, *bin2;
    hal_float_t *fin, *fout;
    hal_s32_t *sin;
    hal_u32_t *uout;
    hal_s64_t *lio;
    hal_u64_t *kin;
    hal_port_t *pin_in, *pin_out, *pin_in2;
    hal_float_t gain;
    hal_s32_t count;
    hal_bit_t flag;
    hal_float_t **real_ref;
    hal_bit_t **bool_ref;
    hal_s32_t *si32_ref;
};

/* Components, ids, names, pins and params. */
static int test_comps(struct pins **pp)
{
    char longname[80];
    struct pins *p;
    int id, id2;

    id = hal_init("core");
    show("hal_init core (first: lib + comp ids)", id);
    show("hal_init core again", hal_init("core"));
    memset(longname, 'x', 56);
    longname[56] = 0;
    show("hal_init 56-char name", hal_init(longname));
    longname[55] = 0;
    id2 = hal_init(longname);
    show("hal_init 55-char name", id2);
    show("hal_exit 55-char comp", hal_exit(id2));
    p = hal_malloc(sizeof(*p));
    *pp = p;
    printf("hal_malloc aligned16=%d\n", ((unsigned long)p & 15) == 0);
    printf("hal_malloc(1) aligned8=%d\n", ((unsigned long)hal_malloc(1) & 7) == 0);
    printf("hal_malloc(24) aligned16=%d\n", ((unsigned long)hal_malloc(24) & 15) == 0);
    show("pin bit in", hal_pin_bit_new("core.b-in", HAL_IN, &p->bin, id));
    show("pin bit out", hal_pin_bit_newf(HAL_OUT, &p->bout, id, "core.%s", "b-out"));
    show("pin bit io", hal_pin_bit_new("core.b-io", HAL_IO, &p->bio, id));
    show("pin bit in2", hal_pin_bit_new("core.b-in2", HAL_IN, &p->bin2, id));
    show("pin float in", hal_pin_float_new("core.f-in", HAL_IN, &p->fin, id));
    show("pin float out", hal_pin_float_new("core.f-out", HAL_OUT, &p->fout, id));
    show("pin s32 in", hal_pin_s32_new("core.s-in", HAL_IN, &p->sin, id));
    show("pin u32 out", hal_pin_u32_new("core.u-out", HAL_OUT, &p->uout, id));
    show("pin s64 io", hal_pin_s64_new("core.l-io", HAL_IO, &p->lio, id));
    show("pin u64 in", hal_pin_u64_new("core.k-in", HAL_IN, &p->kin, id));
    show("pin port in", hal_pin_port_new("core.p-in", HAL_IN, &p->pin_in, id));
    show("pin port out", hal_pin_port_new("core.p-out", HAL_OUT, &p->pin_out, id));
    show("pin port in2", hal_pin_port_new("core.p-in2", HAL_IN, &p->pin_in2, id));
    show("pin port io (refused)", hal_pin_port_new("core.p-io", HAL_IO, &p->pin_in, id));
    show("pin duplicate", hal_pin_bit_new("core.b-in", HAL_IN, &p->bin, id));
    longname[55] = 'x';
    show("pin 56-char name", hal_pin_bit_new(longname, HAL_IN, &p->bin, id));
    longname[50] = 0;
    show("pin newf overflow", hal_pin_bit_newf(HAL_IN, &p->bin, id, "%s.too-long", longname));
    show("pin bad dir", hal_pin_bit_new("core.bad", (hal_pin_dir_t)HAL_RO, &p->bin, id));
    show("pin data not in shm", hal_pin_bit_new("core.bad", HAL_IN, (hal_bit_t **)&longname, id));
    show("new-API pin real default 1.5", hal_pin_new_real(id, HAL_OUT, &p->real_ref, 1.5, "core.n-%s", "real"));
    show("new-API param si32 default -7", hal_param_new_si32(id, HAL_RW, &p->si32_ref, -7, "core.n-si32"));
    show("new-API pin bool default TRUE", hal_pin_new_bool(id, HAL_IN, &p->bool_ref, 1, "core.n-bool"));
    value("core.n-real", 0);
    value("core.n-si32", 0);
    printf("accessors: %g %d\n", hal_get_real(p->real_ref), hal_get_bool(p->bool_ref));
    hal_set_real(p->real_ref, 3.25);
    value("core.n-real", 0);
    show("param float rw", hal_param_float_new("core.gain", HAL_RW, &p->gain, id));
    show("param s32 ro", hal_param_s32_new("core.count", HAL_RO, &p->count, id));
    show("param bit named like a pin", hal_param_bit_new("core.b-in", HAL_RW, &p->flag, id));
    show("param duplicate", hal_param_bit_new("core.gain", HAL_RW, &p->flag, id));
    show("param port type", hal_param_new("core.pp", HAL_PORT, HAL_RW, (void *)&p->flag, id));
    show("export_funct without code", hal_export_funct("core.f", NULL, NULL, 0, 0, id));
    show("export_funct from user comp", hal_export_funct("core.f", nop_funct, NULL, 0, 0, id));
    show("create_thread from user process", hal_create_thread("t", 1000000, 1));
    show("thread_delete from user process", hal_thread_delete("t"));
    show("addf missing funct", hal_add_funct_to_thread("core.f", "t", -1));
    show("hal_ready", hal_ready(id));
    show("hal_ready again", hal_ready(id));
    show("pin after ready", hal_pin_bit_new("core.late", HAL_IN, &p->bin, id));
    show("hal_unready", hal_unready(id));
    show("hal_unready again", hal_unready(id));
    show("hal_set_unready (no-op)", hal_set_unready(id));
    show("hal_ready", hal_ready(id));
    list_pins();
    return id;
}

/* Signals, link rules and value inheritance. */
static void test_links(struct pins *p)
{
    hal_data_u v = {0};

    *p->bout = 1;
    show("newsig a bit", hal_signal_new("a", HAL_BIT));
    show("newsig a again", hal_signal_new("a", HAL_BIT));
    show("newsig f float", hal_signal_new("f", HAL_FLOAT));
    show("newsig io s64", hal_signal_new("io", HAL_S64));
    show("newsig port", hal_signal_new("port", HAL_PORT));
    show("newsig bad type", hal_signal_new("bad", 9));
    show("link missing pin", hal_link("core.nope", "a"));
    show("link missing sig", hal_link("core.b-in", "nope"));
    show("link type mismatch", hal_link("core.f-in", "a"));
    v.b = 1;
    show("setp core.b-in2 TRUE", hal_set_p("core.b-in2", HAL_BIT, &v));
    show("link b-in2 first (inherits TRUE)", hal_link("core.b-in2", "a"));
    value("a", 1);
    show("link b-out (OUT overrides)", hal_link("core.b-out", "a"));
    *p->bout = 0;
    value("a", 1);
    value("core.b-in2", 0);
    show("link b-out again (warning)", hal_link("core.b-out", "a"));
    show("link b-out elsewhere", hal_link("core.b-out", "f"));
    show("link b-io to sig with OUT", hal_link("core.b-io", "a"));
    show("newsig b bit", hal_signal_new("b", HAL_BIT));
    show("link b-io", hal_link("core.b-io", "b"));
    show("link b-out to sig with IO", hal_link("core.b-out", "b"));
    show("sets a (has writer)", hal_set_s("a", HAL_BIT, &v));
    show("sets b (IO only)", hal_set_s("b", HAL_BIT, &v));
    printf("pin core.b-io reads %d\n", *p->bio);
    show("setp linked pin", hal_set_p("core.b-io", HAL_BIT, &v));
    show("setp OUT pin", hal_set_p("core.b-out", HAL_BIT, &v));
    show("setp RO param", hal_set_p("core.count", HAL_S32, &v));
    show("setp wrong type", hal_set_p("core.gain", HAL_BIT, &v));
    show("setp missing", hal_set_p("core.nope", HAL_BIT, &v));
    show("link l-io", hal_link("core.l-io", "io"));
    show("link p-in", hal_link("core.p-in", "port"));
    show("link p-in2 (second reader)", hal_link("core.p-in2", "port"));
    show("link p-out", hal_link("core.p-out", "port"));
    list_sigs();
    show("unlink b-io (keeps value)", hal_unlink("core.b-io"));
    value("core.b-io", 0);
    show("unlink missing", hal_unlink("core.nope"));
    show("delsig b", hal_signal_delete("b"));
    show("delsig b again", hal_signal_delete("b"));
    show("delsig a (pins keep value)", hal_signal_delete("a"));
    value("core.b-in2", 0);
}

/* Port buffers: allocation once, N-1 capacity, all-or-nothing transfers. */
static void test_ports(struct pins *p)
{
    hal_data_u v = {0};
    char buf[8] = {0};

    value("port", 1);
    v.u = 4;
    show("sets port 4", hal_set_s("port", HAL_PORT, &v));
    show("sets port again", hal_set_s("port", HAL_PORT, &v));
    value("port", 1);
    printf("writable=%u readable=%u\n", hal_port_writable(p->pin_out), hal_port_readable(p->pin_in));
    printf("write 4 bytes: %d\n", hal_port_write(p->pin_out, "abcd", 4));
    printf("write 3 bytes: %d\n", hal_port_write(p->pin_out, "abc", 3));
    printf("peek 2: %d %.2s readable=%u\n", hal_port_peek(p->pin_in, buf, 2), buf, hal_port_readable(p->pin_in));
    printf("read 4: %d\n", hal_port_read(p->pin_in, buf, 4));
    printf("read 3: %d %.3s\n", hal_port_read(p->pin_in, buf, 3), buf);
    printf("write wraps: %d\n", hal_port_write(p->pin_out, "xyz", 3));
    printf("read wraps: %d %.3s\n", hal_port_read(p->pin_in, buf, 3), buf);
    show("unlink p-in (port pin becomes empty)", hal_unlink("core.p-in"));
    printf("unlinked port size=%u\n", hal_port_buffer_size(p->pin_in));
}

/* Aliases: both names resolve, listing shows the alias in sorted order. */
static void test_aliases(void)
{
    hal_data_u v = {.f = 2.5};

    show("alias pin core.f-in -> aa.fin", hal_pin_alias("core.f-in", "aa.fin"));
    show("link by original name", hal_link("core.f-in", "f"));
    show("setp by alias (linked)", hal_set_p("aa.fin", HAL_FLOAT, &v));
    show("alias to existing pin name", hal_pin_alias("core.s-in", "core.k-in"));
    show("alias missing pin", hal_pin_alias("core.nope", "zz"));
    show("re-alias core.f-in -> zz.fin", hal_pin_alias("core.f-in", "zz.fin"));
    list_pins();
    show("unalias zz.fin", hal_pin_alias("zz.fin", NULL));
    show("unalias again (no-op)", hal_pin_alias("core.f-in", NULL));
    show("alias param core.gain -> g", hal_param_alias("core.gain", "g"));
    show("setp by original param name", hal_set_p("core.gain", HAL_FLOAT, &v));
    value("g", 0);
    list_sigs();
}

/* Lock levels block the calls of spec/hal.md §10. */
static void test_locks(int id, struct pins *p)
{
    hal_data_u v = {.b = 1};

    show("lock tune", hal_set_lock(HAL_LOCK_TUNE));
    printf("get_lock=%d\n", hal_get_lock());
    show("newsig while locked", hal_signal_new("c", HAL_BIT));
    show("link while locked", hal_link("core.b-in", "f"));
    show("unlink while locked", hal_unlink("core.f-in"));
    show("delsig while locked", hal_signal_delete("f"));
    show("alias while locked", hal_pin_alias("core.b-in", "q"));
    hal_unready(id);
    show("pin_new while locked", hal_pin_bit_new("core.late", HAL_IN, &p->bin, id));
    show("setp while locked (not blocked)", hal_set_p("core.b-in", HAL_BIT, &v));
    show("start while tune-locked", hal_start_threads());
    show("lock all", hal_set_lock(HAL_LOCK_ALL));
    show("start while all-locked", hal_start_threads());
    show("param_set while all-locked", hal_param_float_set("core.gain", 1.0));
    show("unlock", hal_set_lock(HAL_LOCK_NONE));
    show("param_set unlocked", hal_param_float_set("core.gain", 1.0));
    show("param_set RO", hal_param_s32_set("core.count", 1));
    hal_ready(id);
}

/* Streams: depth D holds D-1 records; sample numbers only on success. */
static void test_streams(int id)
{
    hal_stream_t w, r;
    union hal_stream_data rec[2];
    unsigned sample;
    int i;

    show("stream create bad types", hal_stream_create(&w, id, 0x4f454d10, 4, "fx"));
    show("stream create fu depth 4", hal_stream_create(&w, id, 0x4f454d10, 4, "fu"));
    show("stream attach wrong types", hal_stream_attach(&r, id, 0x4f454d10, "bb"));
    show("stream attach missing key", hal_stream_attach(&r, id, 0x4f454d11, NULL));
    show("stream attach", hal_stream_attach(&r, id, 0x4f454d10, "FU"));
    printf("elements=%d type0=%d type1=%d maxdepth=%d\n", hal_stream_element_count(&r),
           hal_stream_element_type(&r, 0), hal_stream_element_type(&r, 1), hal_stream_maxdepth(&r));
    for (i = 0; i < 4; i++) {
        rec[0].f = i + 0.5;
        rec[1].u = 10 * i;
        show("stream write", hal_stream_write(&w, rec));
    }
    printf("depth=%d overruns=%d writable=%d\n", hal_stream_depth(&r), hal_stream_num_overruns(&r),
           hal_stream_writable(&w));
    while (hal_stream_read(&r, rec, &sample) == 0)
        printf("read sample %u: %g %u\n", sample, rec[0].f, rec[1].u);
    printf("underruns=%d\n", hal_stream_num_underruns(&r));
    rec[1].u = 99;
    show("stream write after drain", hal_stream_write(&w, rec));
    show("stream read", hal_stream_read(&r, rec, &sample));
    printf("sample %u value %u\n", sample, rec[1].u);
    hal_stream_detach(&r);
    hal_stream_destroy(&w);
    show("stream attach after destroy", hal_stream_attach(&r, id, 0x4f454d10, NULL));
}

/* Ids, fork re-attach, exit and statistics. */
static void test_ids(int id)
{
    hal_stats_t st;
    hal_comp_info_t info;
    int id2 = hal_init("second");
    int id3;

    show("hal_init second (one id)", id2);
    list_comps();
    id3 = hal_reattach_for_fork(id);
    show("reattach core for fork (+2 ids)", id3);
    list_comps();
    show("comp_by_name core", hal_comp_by_name("core", &info));
    printf("info id=%d ready=%d type=%d\n", info.comp_id, info.ready, info.type);
    show("comp_by_id old id", hal_comp_by_id(id, &info));
    show("hal_exit second", hal_exit(id2));
    hal_statistics(&st);
    printf("stats comps=%d/%d pins=%d/%d params=%d/%d aliases=%d/%d sigs=%d/%d\n",
           st.comps_active, st.comps_recycled, st.pins_active, st.pins_recycled,
           st.params_active, st.params_recycled, st.aliases_active, st.aliases_recycled,
           st.sigs_active, st.sigs_recycled);
    show("hal_exit core", hal_exit(id3));
    printf("mapped after last exit=%d\n", hal_is_init());
}

/* Run every section in order; output is compared with expected. */
int main(void)
{
    struct pins *p;
    int id;

    setvbuf(stdout, NULL, _IONBF, 0);
    printf("strerror: %s / %s / %s / %s\n", hal_strerror(-EPERM), hal_strerror(-EISCONN),
           hal_strerror(-EPROTO), hal_strerror(-1234));
    printf("extend_counter: %lld %lld\n", (long long)hal_extend_counter(0xfff0, 0x0010, 16),
           (long long)hal_extend_counter(0x10005, 0xfffe, 16));
    id = test_comps(&p);
    test_links(p);
    test_ports(p);
    test_aliases();
    test_locks(id, p);
    test_streams(id);
    test_ids(id);
    return 0;
}
