// emc_channel.cc: EmcChannel, a libnml channel whose messages are checked against the EMC message table.
#include "emc_channel.hh"

#include <cerrno>
#include <cstring>

#include "emc_cmd_task.hh"

// Open a channel.
std::unique_ptr<EmcChannel> EmcChannel::open(const std::string &nml_file,
                                             const std::string &buffer,
                                             const std::string &process, std::string *error)
{
    char err[512] = "";
    nml_channel_t *ch = nml_open(nml_file.c_str(), buffer.c_str(), process.c_str(), err,
                                 sizeof err);
    if (!ch) {
        int saved = errno;
        if (error) *error = err;
        errno = saved;
        return nullptr;
    }
    return std::unique_ptr<EmcChannel>(new EmcChannel(ch, buffer));
}

// A read buffer as large as the largest message the buffer takes.
EmcChannel::EmcChannel(nml_channel_t *ch, const std::string &name)
    : ch_(ch), name_(name), buf_size_(nml_max_message(ch))
{
    size_t slots = (buf_size_ + sizeof(max_align_t) - 1) / sizeof(max_align_t);
    buf_.reset(new max_align_t[slots ? slots : 1]);
}

// Detach (a master removes the buffer).
EmcChannel::~EmcChannel()
{
    nml_close(ch_);
}

// Text of a libnml error code for this buffer.
static std::string nml_error_text(const std::string &name, int rc)
{
    switch (rc) {
    case -EACCES: return name + ": this process has no access for that (see its P line)";
    case -EMSGSIZE: return name + ": message larger than the buffer";
    case -EAGAIN: return name + ": queue is full";
    case -EBUSY: return name + ": the previous message has not been read yet (confirm_write)";
    case -ESHUTDOWN: return name + ": buffer was removed by its master";
    case -EIO: return name + ": buffer contents were corrupt and have been dropped";
    default: return name + ": " + strerror(-rc);
    }
}

// Check and write.
int EmcChannel::write(const NMLmsg &msg, int32_t *serial)
{
    std::string why;
    error_.clear();
    if (emc_msg_check(&msg, msg.size, &why) < 0) {
        error_ = name_ + ": refused to write: " + why;
        return last_rc_ = -EBADMSG;
    }
    int rc = nml_write(ch_, &msg, serial);
    if (rc < 0) error_ = nml_error_text(name_, rc);
    return last_rc_ = rc;
}

// Read or peek into the buffer, then check the bytes before handing them out.
const NMLmsg *EmcChannel::fetch(bool remove)
{
    std::string why;
    error_.clear();
    last_rc_ = 0;
    int rc = remove ? nml_read(ch_, buf_.get(), buf_size_) : nml_peek(ch_, buf_.get(), buf_size_);
    if (rc == 0) return nullptr;
    if (rc < 0) {
        error_ = nml_error_text(name_, rc);
        last_rc_ = rc;
        return nullptr;
    }
    if (emc_msg_check(buf_.get(), static_cast<size_t>(rc), &why) < 0) {
        error_ = name_ + ": refused a message: " + why;
        last_rc_ = -EBADMSG;
        return nullptr;
    }
    return reinterpret_cast<const NMLmsg *>(buf_.get());
}

const NMLmsg *EmcChannel::read() { return fetch(true); }
const NMLmsg *EmcChannel::peek() { return fetch(false); }

// Refusal of peek_as: the message is of another class.
int EmcChannel::refuse_type(NMLTYPE got, NMLTYPE want)
{
    error_ = name_ + ": expected " + emc_symbol_lookup(want) + ", found " +
             emc_symbol_lookup(got) + " (type " + std::to_string(got) + ")";
    return last_rc_ = -EBADMSG;
}

uint32_t EmcChannel::change_count() const { return nml_change_count(ch_); }

// Wait for a change, timeout in seconds (< 0 = forever).
int EmcChannel::wait_change(uint32_t seen, double timeout_s)
{
    int64_t ns = timeout_s < 0 ? -1 : static_cast<int64_t>(timeout_s * 1e9);
    return nml_wait_change(ch_, seen, ns);
}

int EmcChannel::queue_count() const { return nml_queue_count(ch_); }
uint64_t EmcChannel::write_count() const { return nml_write_count(ch_); }
bool EmcChannel::alive() const { return nml_alive(ch_) != 0; }

// Build a text message of class M with its text field set, and write it.
template <class M>
static int send_text(EmcChannel &ch, char (M::*field)[LINELEN], const char *text)
{
    M m;
    emc_set_text(m.*field, text);
    return ch.write(m);
}

// Fill and write an operator message of the given kind.
int emc_send_operator_message(EmcChannel &ch, NMLTYPE kind, const char *text)
{
    switch (kind) {
    case EMC_OPERATOR_ERROR_TYPE: return send_text(ch, &EMC_OPERATOR_ERROR::error, text);
    case EMC_OPERATOR_TEXT_TYPE: return send_text(ch, &EMC_OPERATOR_TEXT::text, text);
    case EMC_OPERATOR_DISPLAY_TYPE: return send_text(ch, &EMC_OPERATOR_DISPLAY::display, text);
    case NML_ERROR_TYPE: return send_text(ch, &NML_ERROR::error, text);
    case NML_TEXT_TYPE: return send_text(ch, &NML_TEXT::text, text);
    case NML_DISPLAY_TYPE: return send_text(ch, &NML_DISPLAY::display, text);
    default: return -EINVAL;
    }
}
