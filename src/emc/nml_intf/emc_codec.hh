// emc_codec.hh: checking raw bytes against the message table, checked downcasts, type names and text fields.
#ifndef EMC_CODEC_HH
#define EMC_CODEC_HH

#include <cstddef>
#include <cstring>
#include <string>

#include "nml_base.hh"

// Name of a message type without _TYPE ("EMC_JOINT_HOME"), "UNKNOWN" for other numbers.
const char *emc_symbol_lookup(NMLTYPE type);
// True when type is one of EMC_MSG_LIST.
bool emc_msg_known(NMLTYPE type);
// sizeof the class of type, 0 when unknown.
size_t emc_msg_size(NMLTYPE type);
// The largest message class (EMC_STAT).
size_t emc_msg_max_size();

// 0 when data[0..len) holds one well-formed message: known type, header size equal to the
// class size and to len, every text field NUL-terminated. Otherwise -EBADMSG and *why (may
// be NULL) says what is wrong, e.g. "message type 9999 is unknown" or
// "EMC_TASK_SET_MODE: size 20, expected 24".
int emc_msg_check(const void *data, size_t len, std::string *why);

// Checked downcast: msg as class M when its type and size are M's, else nullptr. Only
// messages that passed emc_msg_check (as every EmcChannel read does) should be cast.
template <class M>
const M *emc_msg_as(const NMLmsg *msg)
{
    if (!msg || msg->type != M::TYPE || msg->size != sizeof(M)) return nullptr;
    return static_cast<const M *>(msg);
}

// Copy text into a fixed text field, NUL-terminated; false when it had to be truncated.
template <size_t N>
bool emc_set_text(char (&field)[N], const char *text)
{
    size_t len = text ? strlen(text) : 0;
    size_t copy = len < N ? len : N - 1;
    memcpy(field, text ? text : "", copy);
    memset(field + copy, 0, N - copy);
    return copy == len;
}

#endif
