// emc_codec.cc: the message table (type, name, size, text fields) and the checks every read and write goes through.
#include "emc_codec.hh"

#include <algorithm>
#include <cerrno>
#include <cstdio>

#include "emc_nml.hh"

namespace {

// True when a fixed text field holds a NUL.
template <size_t N>
bool terminated(const char (&field)[N])
{
    return memchr(field, 0, N) != nullptr;
}

// Record why a text field is bad; always false.
bool bad_text(std::string *why, const char *message, const char *field)
{
    if (why) *why = std::string(message) + ": text field '" + field + "' is not NUL-terminated";
    return false;
}

// Text-field check of a message class: none by default.
template <class M>
bool texts_ok(const M &, std::string *)
{
    return true;
}

// Classes with text fields, each listing them.
#define ONE_TEXT(cls, field)                                                   \
    template <>                                                                \
    bool texts_ok<cls>(const cls &m, std::string *why)                         \
    {                                                                          \
        return terminated(m.field) || bad_text(why, #cls, #field);             \
    }
ONE_TEXT(NML_ERROR, error)
ONE_TEXT(NML_TEXT, text)
ONE_TEXT(NML_DISPLAY, display)
ONE_TEXT(EMC_OPERATOR_ERROR, error)
ONE_TEXT(EMC_OPERATOR_TEXT, text)
ONE_TEXT(EMC_OPERATOR_DISPLAY, display)
ONE_TEXT(EMC_SYSTEM_CMD, string)
ONE_TEXT(EMC_JOINT_LOAD_COMP, file)
ONE_TEXT(EMC_TASK_PLAN_OPEN, file)
ONE_TEXT(EMC_TASK_PLAN_EXECUTE, command)
ONE_TEXT(EMC_TOOL_LOAD_TOOL_TABLE, file)
ONE_TEXT(EMC_TOOL_STAT, toolTableCurrent.comment)
#undef ONE_TEXT

template <>
bool texts_ok<EMC_TASK_STAT>(const EMC_TASK_STAT &m, std::string *why)
{
    if (!terminated(m.file)) return bad_text(why, "EMC_TASK_STAT", "file");
    if (!terminated(m.command)) return bad_text(why, "EMC_TASK_STAT", "command");
    if (!terminated(m.ini_filename)) return bad_text(why, "EMC_TASK_STAT", "ini_filename");
    return true;
}

template <>
bool texts_ok<EMC_IO_STAT>(const EMC_IO_STAT &m, std::string *why)
{
    return texts_ok(m.tool, why);
}

template <>
bool texts_ok<EMC_STAT>(const EMC_STAT &m, std::string *why)
{
    return texts_ok(m.task, why) && texts_ok(m.io, why);
}

// Type-erased text check of class M.
template <class M>
bool texts_thunk(const void *data, std::string *why)
{
    return texts_ok(*static_cast<const M *>(data), why);
}

struct MsgInfo {
    NMLTYPE type;
    const char *name;
    size_t size;
    bool (*texts)(const void *, std::string *);
};

#define EMC_MSG_ROW(name, number) {number, #name, sizeof(name), &texts_thunk<name>},
const MsgInfo msg_table[] = {EMC_MSG_LIST(EMC_MSG_ROW)};
#undef EMC_MSG_ROW
const size_t msg_count = sizeof(msg_table) / sizeof(msg_table[0]);

// Table row of type (the list is in ascending type order), or nullptr.
const MsgInfo *find_info(NMLTYPE type)
{
    const MsgInfo *end = msg_table + msg_count;
    const MsgInfo *row = std::lower_bound(msg_table, end, type,
                                          [](const MsgInfo &r, NMLTYPE t) { return r.type < t; });
    return row != end && row->type == type ? row : nullptr;
}

// Record a refusal; always -EBADMSG.
int refuse(std::string *why, const std::string &text)
{
    if (why) *why = text;
    return -EBADMSG;
}

} // namespace

// Name of a type without _TYPE.
const char *emc_symbol_lookup(NMLTYPE type)
{
    const MsgInfo *row = find_info(type);
    return row ? row->name : "UNKNOWN";
}

// Whether the type is in the table.
bool emc_msg_known(NMLTYPE type)
{
    return find_info(type) != nullptr;
}

// Size of the class of a type.
size_t emc_msg_size(NMLTYPE type)
{
    const MsgInfo *row = find_info(type);
    return row ? row->size : 0;
}

// Largest class in the table.
size_t emc_msg_max_size()
{
    size_t max = 0;
    for (const MsgInfo &row : msg_table) max = std::max(max, row.size);
    return max;
}

// Check a raw message: header present, known type, sizes agree, texts terminated.
int emc_msg_check(const void *data, size_t len, std::string *why)
{
    if (!data || len < sizeof(NMLmsg))
        return refuse(why, "message of " + std::to_string(len) + " bytes is shorter than its header");
    nml_msg_hdr_t head;
    memcpy(&head, data, sizeof head);
    const MsgInfo *row = find_info(head.type);
    if (!row) return refuse(why, "message type " + std::to_string(head.type) + " is unknown");
    if (head.size != row->size || len != row->size)
        return refuse(why, std::string(row->name) + ": size " + std::to_string(head.size) +
                               " (" + std::to_string(len) + " bytes received), expected " +
                               std::to_string(row->size));
    if (!row->texts(data, why)) return -EBADMSG;
    return 0;
}
