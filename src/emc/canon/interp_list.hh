// interp_list.hh: the queue of NML messages the interpreter's canon calls produce and task issues in order.
#ifndef INTERP_LIST_HH
#define INTERP_LIST_HH

#include <cstring>
#include <deque>
#include <memory>

#include "nml_base.hh"

// One queued message: a private copy of a plain-data NML message and its source line.
class QueuedMsg {
public:
    // Copy msg (any NML message class) with the source line it came from.
    template <class M>
    static QueuedMsg make(const M &msg, int line)
    {
        QueuedMsg q;
        q.line = line;
        q.copy(&msg, sizeof(M));
        return q;
    }
    // The message (type and size as copied).
    const NMLmsg *msg() const { return reinterpret_cast<const NMLmsg *>(data_.get()); }
    NMLmsg *msg() { return reinterpret_cast<NMLmsg *>(data_.get()); }
    int line = 0;

private:
    void copy(const void *src, size_t size)
    {
        size_t n = (size + sizeof(max_align_t) - 1) / sizeof(max_align_t);
        data_.reset(new max_align_t[n]);
        memcpy(data_.get(), src, size);
    }
    std::shared_ptr<max_align_t[]> data_;
};

// FIFO of queued messages (LinuxCNC's interp_list).
class InterpList {
public:
    // Append msg for source line `line`.
    template <class M>
    void append(const M &msg, int line) { items_.push_back(QueuedMsg::make(msg, line)); ++appended_; }
    bool empty() const { return items_.empty(); }
    size_t size() const { return items_.size(); }
    const QueuedMsg &front() const { return items_.front(); }
    // Append a copy of an item taken from a list.
    void append_copy(const QueuedMsg &q) { items_.push_back(q); ++appended_; }
    QueuedMsg pop() { QueuedMsg q = items_.front(); items_.pop_front(); return q; }
    void clear() { items_.clear(); }
    // Drop everything appended after the first `keep` items (used to discard a skipped line's output).
    void truncate(size_t keep) { while (items_.size() > keep) items_.pop_back(); }
    // Messages appended since creation (never decreases).
    unsigned long appended() const { return appended_; }

private:
    std::deque<QueuedMsg> items_;
    unsigned long appended_ = 0;
};

#endif
