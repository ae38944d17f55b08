// rsh_net.cc: linuxcncrsh's sockets: listening (loopback unless told otherwise, never elsewhere with default passwords), sessions, lines, replies.
#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "rsh.hh"

namespace {

// A request line longer than this is refused and skipped.
const size_t MAX_LINE = 65536;
// Unsent replies beyond this mean the client does not read: it is dropped.
const size_t MAX_PENDING_OUT = 1 << 20;
// Longest sleep of the loop, so a signal is seen soon.
const int POLL_MS = 200;

// True for 127.0.0.0/8, ::1 and ::ffff:127.x.y.z.
bool is_loopback(const struct sockaddr *sa)
{
    if (sa->sa_family == AF_INET) {
        uint32_t a = ntohl(reinterpret_cast<const sockaddr_in *>(sa)->sin_addr.s_addr);
        return (a >> 24) == 127;
    }
    if (sa->sa_family == AF_INET6) {
        const in6_addr &a = reinterpret_cast<const sockaddr_in6 *>(sa)->sin6_addr;
        if (IN6_IS_ADDR_LOOPBACK(&a)) return true;
        return IN6_IS_ADDR_V4MAPPED(&a) && a.s6_addr[12] == 127;
    }
    return false;
}

// "address:port" of a socket address.
std::string address_text(const struct sockaddr *sa)
{
    char host[NI_MAXHOST], port[NI_MAXSERV];
    if (getnameinfo(sa, sa->sa_family == AF_INET6 ? sizeof(sockaddr_in6) : sizeof(sockaddr_in), host,
                    sizeof host, port, sizeof port, NI_NUMERICHOST | NI_NUMERICSERV) != 0)
        return "?";
    return sa->sa_family == AF_INET6 ? std::string("[") + host + "]:" + port : std::string(host) + ":" + port;
}

// The passwords are still LinuxCNC's well-known defaults.
bool default_passwords(const RshOptions &o)
{
    return o.connect_pw == RSH_DEFAULT_CONNECT_PW || o.enable_pw == RSH_DEFAULT_ENABLE_PW;
}

// Listen on one resolved address: the socket, or -errno.
int listen_address(const struct addrinfo *ai)
{
    int fd = socket(ai->ai_family, ai->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, ai->ai_protocol);
    if (fd < 0) return -errno;
    int one = 1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (ai->ai_family == AF_INET6) setsockopt(fd, IPPROTO_IPV6, IPV6_V6ONLY, &one, sizeof one);
    if (bind(fd, ai->ai_addr, ai->ai_addrlen) < 0 || listen(fd, 16) < 0) {
        int e = errno;
        close(fd);
        return -e;
    }
    return fd;
}

// Listen on every address host resolves to. 0, or 1 after a message. Loopback hosts of the
// default pair may be missing (a machine without IPv6): *soft makes that silent.
int listen_host(RshServer &sv, const std::string &host, bool soft)
{
    struct addrinfo hints, *res = nullptr;
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
    std::string port = std::to_string(sv.opt.port);
    int rc = getaddrinfo(host.empty() ? nullptr : host.c_str(), port.c_str(), &hints, &res);
    if (rc != 0) {
        if (soft) return 0;
        fprintf(stderr, "linuxcncrsh: cannot listen on '%s': %s\n", host.c_str(), gai_strerror(rc));
        return 1;
    }
    int status = 0;
    for (struct addrinfo *ai = res; ai && status == 0; ai = ai->ai_next) {
        if (!is_loopback(ai->ai_addr) && default_passwords(sv.opt)) {
            fprintf(stderr, "linuxcncrsh: refusing to listen on %s: the connect and enable passwords "
                            "are still LinuxCNC's defaults; choose your own with --connectpw and "
                            "--enablepw to accept connections from other hosts\n",
                    address_text(ai->ai_addr).c_str());
            status = 1;
            break;
        }
        int fd = listen_address(ai);
        if (fd >= 0) {
            sv.listeners.push_back(fd);
            if (!sv.opt.quiet) printf("linuxcncrsh: listening on %s\n", address_text(ai->ai_addr).c_str());
        } else if (!(soft && (fd == -EADDRNOTAVAIL || fd == -EAFNOSUPPORT))) {
            fprintf(stderr, "linuxcncrsh: cannot listen on %s: %s\n", address_text(ai->ai_addr).c_str(),
                    strerror(-fd));
            status = 1;
        }
    }
    freeaddrinfo(res);
    return status;
}

// Send what can be sent now; false when the connection is broken or not reading.
bool flush(RshSession &s)
{
    while (!s.out.empty()) {
        ssize_t n = send(s.fd, s.out.data(), s.out.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n > 0) {
            s.out.erase(0, static_cast<size_t>(n));
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            return s.out.size() <= MAX_PENDING_OUT;
        } else {
            return false;
        }
    }
    return true;
}

// Accept one connection on a listening socket.
void accept_one(RshServer &sv, int lfd)
{
    struct sockaddr_storage addr;
    socklen_t len = sizeof addr;
    int fd = accept4(lfd, reinterpret_cast<sockaddr *>(&addr), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;
    std::string peer = address_text(reinterpret_cast<sockaddr *>(&addr));
    if (sv.opt.max_sessions > 0 && static_cast<int>(sv.sessions.size()) >= sv.opt.max_sessions) {
        static const char msg[] = "error: too many sessions\r\n";
        (void)!send(fd, msg, sizeof msg - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
        close(fd);
        fprintf(stderr, "linuxcncrsh: %s refused: %d sessions already\n", peer.c_str(), sv.opt.max_sessions);
        return;
    }
    std::unique_ptr<RshSession> s(new RshSession);
    s->fd = fd;
    s->id = sv.next_id++;
    s->peer = peer;
    if (!sv.opt.quiet) printf("linuxcncrsh: connection from %s\n", peer.c_str());
    sv.sessions.push_back(std::move(s));
}

// Take the next complete line out of s.in (or all of it at end of input).
bool next_line(RshSession &s, bool eof, std::string *line)
{
    size_t end = s.in.find_first_of("\r\n");
    if (end == std::string::npos) {
        if (!eof || s.in.empty()) return false;
        end = s.in.size();
    }
    *line = s.in.substr(0, end);
    size_t skip = s.in.find_first_not_of("\r\n", end);
    s.in.erase(0, skip == std::string::npos ? s.in.size() : skip);
    return true;
}

// Read what arrived and serve every complete line; false once the session is over.
bool serve_session(RshServer &sv, RshSession &s, const volatile std::sig_atomic_t *stop)
{
    char buf[4096];
    bool eof = false;
    for (;;) {
        ssize_t n = recv(s.fd, buf, sizeof buf, MSG_DONTWAIT);
        if (n > 0) {
            s.in.append(buf, static_cast<size_t>(n));
            continue;
        }
        if (n < 0 && errno == EINTR) continue;
        eof = n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK);
        break;
    }
    std::string line;
    while (!s.closing && !sv.shutdown && !*stop && next_line(s, eof, &line)) {
        rsh_handle_line(sv, s, line);
        if (!flush(s)) return false;
    }
    if (s.in.size() > MAX_LINE) {
        s.reply("error: request longer than " + std::to_string(MAX_LINE) + " bytes");
        s.in.clear();
    }
    if (!flush(s)) return false;
    return !eof && !(s.closing && s.out.empty());
}

// Close a session (control goes back to nobody if it held it).
void close_session(RshServer &sv, size_t i)
{
    RshSession &s = *sv.sessions[i];
    if (sv.enabled_id == s.id) sv.enabled_id = 0;
    if (!sv.opt.quiet) printf("linuxcncrsh: %s disconnected\n", s.peer.c_str());
    close(s.fd);
    sv.sessions.erase(sv.sessions.begin() + static_cast<long>(i));
}

} // namespace

// Open the listening sockets: --bind addresses, else 127.0.0.1 and ::1.
int rsh_listen(RshServer &sv)
{
    bool defaults = sv.opt.bind.empty();
    std::vector<std::string> hosts = defaults ? std::vector<std::string>{"127.0.0.1", "::1"} : sv.opt.bind;
    for (const std::string &h : hosts)
        if (listen_host(sv, h, defaults && h == "::1") != 0) return 1;
    if (sv.listeners.empty()) {
        fprintf(stderr, "linuxcncrsh: no address to listen on\n");
        return 1;
    }
    return 0;
}

// Serve connections until 'shutdown' or a signal.
int rsh_serve(RshServer &sv, const volatile std::sig_atomic_t *stop)
{
    while (!*stop && !sv.shutdown) {
        std::vector<struct pollfd> fds;
        for (int fd : sv.listeners) fds.push_back({fd, POLLIN, 0});
        for (auto &s : sv.sessions) fds.push_back({s->fd, static_cast<short>(POLLIN | (s->out.empty() ? 0 : POLLOUT)), 0});
        if (poll(fds.data(), fds.size(), POLL_MS) < 0 && errno != EINTR) {
            perror("linuxcncrsh: poll");
            return 1;
        }
        for (size_t i = 0; i < sv.listeners.size(); i++)
            if (fds[i].revents & POLLIN) accept_one(sv, sv.listeners[i]);
        size_t base = sv.listeners.size();
        size_t polled = fds.size() - base;
        for (size_t i = polled; i-- > 0;) {
            if (!fds[base + i].revents) continue;
            if (!serve_session(sv, *sv.sessions[i], stop)) close_session(sv, i);
            if (sv.shutdown) break;
        }
    }
    for (size_t i = sv.sessions.size(); i-- > 0;) {
        flush(*sv.sessions[i]);
        close_session(sv, i);
    }
    for (int fd : sv.listeners) close(fd);
    sv.listeners.clear();
    return 0;
}
