// ui_client.cc: attaching emcCommand/emcStatus/emcError as "xemc", polling status, writing commands and waiting for task's echo.
#include "ui_client.hh"

#include <signal.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace {

// Longest single sleep of a wait, so the stop flag is seen soon after a signal.
const double WAIT_SLICE_S = 0.05;

} // namespace

// Wrap-safe serial difference.
int32_t ui_serial_diff(int32_t a, int32_t b)
{
    return static_cast<int32_t>(static_cast<uint32_t>(a) - static_cast<uint32_t>(b));
}

// Monotonic seconds.
double ui_now_s()
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

// The signals that end a user interface's loop.
void ui_install_stop_signals(void (*handler)(int))
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGHUP, &sa, nullptr);
}

UiClient::UiClient(std::string nml_file) : nml_file_(std::move(nml_file)), status_(new EMC_STAT) {}

UiClient::~UiClient() = default;

// Open one buffer unless it is open and still alive.
bool UiClient::link(std::unique_ptr<EmcChannel> &ch, const char *buffer)
{
    if (ch && ch->alive()) return true;
    ch.reset();
    std::string why;
    ch = EmcChannel::open(nml_file_, buffer, "xemc", &why);
    if (!ch) error_ = why;
    return ch != nullptr;
}

// Attach all three buffers.
bool UiClient::attach()
{
    bool ok = link(cmd_, "emcCommand");
    ok = link(stat_, "emcStatus") && ok;
    ok = link(err_, "emcError") && ok;
    return ok;
}

// Copy the newest status.
int UiClient::poll()
{
    if (!link(stat_, "emcStatus")) return 0;
    int rc = stat_->peek_as(*status_);
    if (rc < 0) {
        error_ = "emcStatus: " + stat_->error();
        return -1;
    }
    if (rc > 0) have_status_ = true;
    return rc;
}

// Write one command.
int UiClient::send(const NMLmsg &msg)
{
    if (!link(cmd_, "emcCommand") || !link(stat_, "emcStatus")) return -ENOTCONN;
    int32_t serial = 0;
    int rc = cmd_->write(msg, &serial);
    if (rc < 0) {
        error_ = cmd_->error();
        return rc;
    }
    last_serial_ = serial;
    return 0;
}

// Write and wait as asked.
int UiClient::send_and_wait(const NMLmsg &msg, UiWait wait, double timeout_s)
{
    int rc = send(msg);
    if (rc < 0 || wait == UiWait::none) return rc;
    if (wait == UiWait::received) return wait_received(last_serial_, timeout_s);
    return wait_done(last_serial_, timeout_s);
}

// Poll until the echo condition holds; 0 / 1 (done with an error) / negative errno.
int UiClient::wait_until(int32_t serial, bool done, double timeout_s)
{
    double deadline = timeout_s > 0 ? ui_now_s() + timeout_s : 0;
    for (;;) {
        if (!link(stat_, "emcStatus")) {
            error_ = "emcStatus is gone (the machine stopped)";
            return -ESHUTDOWN;
        }
        uint32_t seen = stat_->change_count();
        if (poll() > 0) {
            int32_t diff = ui_serial_diff(status_->echo_serial_number, serial);
            if (!done && diff >= 0) return 0;
            if (done && diff > 0) return 0;
            if (done && diff == 0 && status_->status == RCS_DONE) return 0;
            if (done && diff == 0 && status_->status == RCS_ERROR) return 1;
        }
        if (stopped()) return -EINTR;
        double slice = WAIT_SLICE_S;
        if (deadline > 0) {
            double left = deadline - ui_now_s();
            if (left <= 0) {
                error_ = "timed out waiting for task";
                return -ETIMEDOUT;
            }
            slice = std::min(slice, left);
        }
        int rc = stat_->wait_change(seen, slice);
        if (rc < 0 && rc != -ETIMEDOUT && rc != -EINTR) {
            error_ = stat_->error().empty() ? strerror(-rc) : stat_->error();
            return rc;
        }
    }
}

int UiClient::wait_received(int32_t serial, double timeout_s) { return wait_until(serial, false, timeout_s); }

int UiClient::wait_done(int32_t serial, double timeout_s) { return wait_until(serial, true, timeout_s); }

// Sleep until the status buffer changes.
int UiClient::wait_status_change(double timeout_s)
{
    if (!link(stat_, "emcStatus")) return -ENOTCONN;
    return stat_->wait_change(stat_->change_count(), timeout_s);
}

// Take one operator message.
int UiClient::read_message(NMLTYPE *kind, std::string *text)
{
    if (!link(err_, "emcError")) return -ENOTCONN;
    const NMLmsg *msg = err_->read();
    if (!msg) {
        if (err_->error().empty()) return 0;
        error_ = "emcError: " + err_->error();
        return -EBADMSG;
    }
    *kind = msg->type;
    if (auto *m = emc_msg_as<EMC_OPERATOR_ERROR>(msg)) *text = m->error;
    else if (auto *m = emc_msg_as<EMC_OPERATOR_TEXT>(msg)) *text = m->text;
    else if (auto *m = emc_msg_as<EMC_OPERATOR_DISPLAY>(msg)) *text = m->display;
    else if (auto *m = emc_msg_as<NML_ERROR>(msg)) *text = m->error;
    else if (auto *m = emc_msg_as<NML_TEXT>(msg)) *text = m->text;
    else if (auto *m = emc_msg_as<NML_DISPLAY>(msg)) *text = m->display;
    else *text = std::string("unrecognized error ") + std::to_string(msg->type);
    return 1;
}
