// emc_channel.hh: an NML buffer carrying EMC messages: checked writes and reads over libnml.
#ifndef EMC_CHANNEL_HH
#define EMC_CHANNEL_HH

#include <cstdint>
#include <memory>
#include <string>

#include "emc_codec.hh"
#include "nml.h"

// One process's connection to one buffer of a .nml file, e.g.
//   auto cmd = EmcChannel::open(nml_file, "emcCommand", "emc", &err);
// Every message written is checked first (emc_msg_check); every message read is checked
// before the caller sees it, so a reader never casts bytes it has not validated.
class EmcChannel {
public:
    // Open `buffer` as `process` of the .nml file; nullptr with *error set on failure
    // ("file:line: ..." for a bad file, "emcStatus: ..." for a buffer problem). errno is
    // left as nml_open set it (ENOENT: no master has created the buffer yet).
    static std::unique_ptr<EmcChannel> open(const std::string &nml_file, const std::string &buffer,
                                            const std::string &process, std::string *error);
    ~EmcChannel();
    EmcChannel(const EmcChannel &) = delete;
    EmcChannel &operator=(const EmcChannel &) = delete;

    // Check and write msg. 0 or a negative errno (see nml_write; -EBADMSG: msg is not
    // well-formed); error() says why. *serial gets the serial a `serial` buffer stamped.
    int write(const NMLmsg &msg, int32_t *serial = nullptr);
    // Take the oldest message (queue) or copy the latest one (latest-value buffer). The
    // message stays valid until the next read()/peek(). nullptr when there is none, or
    // when it was refused: then error() is non-empty (a refused queued message is dropped).
    const NMLmsg *read();
    // As read() without removing or marking the message.
    const NMLmsg *peek();
    // Copy the latest/oldest message into out when it is exactly an M: 1 copied, 0 none,
    // -EBADMSG another or malformed message (error() says which), other -errno from libnml.
    template <class M>
    int peek_as(M &out)
    {
        const NMLmsg *msg = peek();
        if (!msg) return error_.empty() ? 0 : last_rc_;
        const M *typed = emc_msg_as<M>(msg);
        if (!typed) return refuse_type(msg->type, M::TYPE);
        out = *typed;
        return 1;
    }

    // Change counter of the buffer (changes on every write and queued read).
    uint32_t change_count() const;
    // Sleep until the change counter differs from seen: 0, -ETIMEDOUT, -EINTR, -ESHUTDOWN.
    int wait_change(uint32_t seen, double timeout_s);
    // Messages waiting in a queue buffer.
    int queue_count() const;
    // Successful writes so far (the last serial handed out).
    uint64_t write_count() const;
    // False once the master removed the buffer (reopen to reattach).
    bool alive() const;
    // Reason of the last failure, "" after a success.
    const std::string &error() const { return error_; }
    // Buffer name (e.g. "emcCommand").
    const std::string &name() const { return name_; }
    // The libnml channel underneath.
    nml_channel_t *raw() const { return ch_; }

private:
    EmcChannel(nml_channel_t *ch, const std::string &name);
    const NMLmsg *fetch(bool remove);
    int refuse_type(NMLTYPE got, NMLTYPE want);

    nml_channel_t *ch_;
    std::string name_;
    std::unique_ptr<max_align_t[]> buf_;
    size_t buf_size_;
    std::string error_;
    int last_rc_ = 0;
};

// Write an operator message of kind EMC_OPERATOR_ERROR/_TEXT/_DISPLAY_TYPE (or NML_*)
// with text truncated to LINELEN - 1 characters. 0 or -errno (-EINVAL: unknown kind).
int emc_send_operator_message(EmcChannel &ch, NMLTYPE kind, const char *text);

// The .nml file of a configuration: [EMC]NML_FILE of the INI file (relative paths are
// taken from the INI file's folder), else emc_default_nml_file(). "" with *error set
// when the INI file cannot be read.
std::string emc_nml_file_for_ini(const std::string &ini_path, std::string *error);
// The default .nml file: $EMC2_HOME/configs/common/linuxcnc.nml, else the one of the tree
// or installation this library belongs to.
std::string emc_default_nml_file();

#endif
