// ui_client.hh: a user interface's link to task (halui, linuxcncrsh): status, commands with "received"/"done" waits, operator messages.
#ifndef UI_CLIENT_HH
#define UI_CLIENT_HH

#include <csignal>
#include <memory>
#include <string>

#include "emc_nml.hh"

// How long to wait after writing a command (LinuxCNC's wait modes).
enum class UiWait { none, received, done };

// The three NML buffers of one configuration, opened as process "xemc". The link attaches
// lazily and re-attaches after the machine was restarted, so a UI may start before task
// and outlive it. Waits sleep on the status buffer's change counter, never in fixed steps.
class UiClient {
public:
    explicit UiClient(std::string nml_file);
    ~UiClient();
    UiClient(const UiClient &) = delete;
    UiClient &operator=(const UiClient &) = delete;

    // Attach the buffers that are not attached yet; true when all three are. error() says
    // what is missing otherwise.
    bool attach();
    // Copy the newest status into status(): 1 copied, 0 no status yet (or not attached),
    // -1 a malformed status (error() says why; the old copy is kept).
    int poll();
    // The last status poll() copied (all zero before the first one).
    const EMC_STAT &status() const { return *status_; }
    // True once poll() copied a status.
    bool have_status() const { return have_status_; }

    // Write a command: 0, or a negative errno (-ENOTCONN: no machine; -EAGAIN: the command
    // queue is full). error() says why. last_serial() is the serial task will echo.
    int send(const NMLmsg &msg);
    int32_t last_serial() const { return last_serial_; }
    // Write, then wait as asked: 0 received/done, 1 done with RCS_ERROR, negative errno
    // (-ETIMEDOUT, -ESHUTDOWN: buffers removed, -EINTR: the stop flag was raised).
    // timeout_s <= 0 waits without a limit.
    int send_and_wait(const NMLmsg &msg, UiWait wait, double timeout_s);
    // Wait until task has read command `serial` (0) or a negative errno as above.
    int wait_received(int32_t serial, double timeout_s);
    // Wait until command `serial` is finished: 0 done, 1 done with RCS_ERROR, or a
    // negative errno as above. poll()ed status is current afterwards.
    int wait_done(int32_t serial, double timeout_s);
    // Wait until the status changed (or timeout_s passed): 0 changed, negative errno.
    int wait_status_change(double timeout_s);

    // Take the oldest operator message from emcError: 1 with *kind (EMC_OPERATOR_ERROR_TYPE,
    // _TEXT_, _DISPLAY_ or NML_*_TYPE) and *text, 0 none, negative errno.
    int read_message(NMLTYPE *kind, std::string *text);

    // Waits end early with -EINTR once *flag is non-zero (a signal handler's flag).
    void set_stop_flag(const volatile std::sig_atomic_t *flag) { stop_flag_ = flag; }
    // True once the stop flag was raised (loops of callers end then too).
    bool stop_requested() const { return stopped(); }
    // Why the last call failed.
    const std::string &error() const { return error_; }
    const std::string &nml_file() const { return nml_file_; }

private:
    bool link(std::unique_ptr<EmcChannel> &ch, const char *buffer);
    int wait_until(int32_t serial, bool done, double timeout_s);
    bool stopped() const { return stop_flag_ && *stop_flag_; }

    std::string nml_file_;
    std::unique_ptr<EmcChannel> cmd_, stat_, err_;
    std::unique_ptr<EMC_STAT> status_;
    bool have_status_ = false;
    int32_t last_serial_ = 0;
    const volatile std::sig_atomic_t *stop_flag_ = nullptr;
    std::string error_;
};

// Wrap-safe difference of two command serials (a - b).
int32_t ui_serial_diff(int32_t a, int32_t b);
// Monotonic clock in seconds.
double ui_now_s();
// SIGTERM, SIGINT and SIGHUP call handler (no SA_RESTART, so a sleep they interrupt ends early).
void ui_install_stop_signals(void (*handler)(int));

#endif
