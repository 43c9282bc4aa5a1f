// The runtime of record and replay (geolab/grading/boundary_calls.hpp): the channel, the bounded reader, the
// encoding of exceptions, and time_student_call.
#include "geolab/grading/boundary_calls.hpp"

#include <cerrno>
#include <csignal>
#include <new>
#include <stdexcept>
#include <typeinfo>

#include <poll.h>
#include <unistd.h>

#include "geolab/errors.hpp"
#include "geolab/grading/test.hpp"

namespace geolab {

namespace wire {

bool Reader::fill() {
    if (pos_ < buf_.size()) return true;
    buf_.clear();
    pos_ = 0;
    char tmp[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd_, tmp, sizeof tmp);
        if (n > 0) {
            buf_.assign(tmp, static_cast<std::size_t>(n));
            return true;
        }
        if (n < 0 && errno == EINTR) continue;
        return false;
    }
}

void Reader::bytes(void* p, std::size_t n) {
    if (n > left()) throw Error(Error::malformed, "the recording is longer than its limit");
    auto* out = static_cast<char*>(p);
    while (n > 0) {
        if (!fill()) throw Error(Error::truncated, "the recording ended in the middle of an answer");
        const std::size_t k = std::min(n, buf_.size() - pos_);
        std::memcpy(out, buf_.data() + pos_, k);
        pos_ += k;
        out += k;
        n -= k;
        consumed_ += k;
    }
}

bool Reader::ready() {
    if (pos_ < buf_.size()) return true;
    pollfd p{fd_, POLLIN, 0};
    return ::poll(&p, 1, 0) > 0 && (p.revents & POLLIN);
}

bool Reader::at_end() { return !fill(); }

}  // namespace wire

namespace boundary {

Channel& channel() {
    static Channel c;
    return c;
}

void stop(const std::string& kind, const std::string& message) {
    Channel& ch = channel();
    if (ch.stop) ch.stop(kind, message);
    std::fputs(message.c_str(), stderr);
    std::fputs("\n", stderr);
    ::_exit(3);
}

namespace {
bool write_all(int fd, const char* p, std::size_t n) {
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w;
        n -= static_cast<std::size_t>(w);
    }
    return true;
}
bool read_all(int fd, char* p, std::size_t n) {
    while (n > 0) {
        const ssize_t r = ::read(fd, p, n);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return false;
        p += r;
        n -= static_cast<std::size_t>(r);
    }
    return true;
}

// Exception tags: the most derived standard or geolab type the exception is.
enum Tag : std::uint8_t {
    t_unknown, t_exception, t_logic, t_invalid_argument, t_domain, t_length, t_out_of_range, t_runtime, t_range,
    t_overflow, t_underflow, t_bad_alloc, t_not_implemented, t_topology, t_io
};
const std::string ni_prefix = "not implemented: ", ni_suffix = " (this is yours to write; see the handout)";
}  // namespace

void send(wire::Writer& w) {
    Channel& ch = channel();
    if (!write_all(ch.data_fd, w.buffer().data(), w.buffer().size())) ::_exit(0);  // the judge is gone
}

void wait_go(std::uint32_t n) {
    std::uint32_t got = 0;
    if (!read_all(channel().go_fd, reinterpret_cast<char*>(&got), sizeof got) || got != n) ::_exit(0);
}

void write_current_exception(wire::Writer& w) {
    auto put = [&](Tag t, const char* what) {
        w.u8(t);
        wire::write(w, std::string(what));
    };
    try {
        throw;
    } catch (const NotImplemented& e) {
        put(t_not_implemented, e.what());
    } catch (const TopologyError& e) {
        put(t_topology, e.what());
    } catch (const IoError& e) {
        put(t_io, e.what());
        wire::write(w, e.file());
        wire::write(w, static_cast<std::uint64_t>(e.line()));
    } catch (const std::invalid_argument& e) {
        put(t_invalid_argument, e.what());
    } catch (const std::domain_error& e) {
        put(t_domain, e.what());
    } catch (const std::length_error& e) {
        put(t_length, e.what());
    } catch (const std::out_of_range& e) {
        put(t_out_of_range, e.what());
    } catch (const std::logic_error& e) {
        put(t_logic, e.what());
    } catch (const std::range_error& e) {
        put(t_range, e.what());
    } catch (const std::overflow_error& e) {
        put(t_overflow, e.what());
    } catch (const std::underflow_error& e) {
        put(t_underflow, e.what());
    } catch (const std::runtime_error& e) {
        put(t_runtime, e.what());
    } catch (const std::bad_alloc& e) {
        put(t_bad_alloc, e.what());
    } catch (const std::exception& e) {
        put(t_exception, e.what());
    } catch (...) {
        put(t_unknown, "an exception that is not a std::exception");
    }
}

namespace {
// What replay throws for an exception that is not one of the standard ones (its message is the original's).
struct RecordedException : std::exception {
    std::string message;
    explicit RecordedException(std::string m) : message(std::move(m)) {}
    const char* what() const noexcept override { return message.c_str(); }
};
}  // namespace

std::exception_ptr read_exception(wire::Reader& r) {
    const std::uint8_t tag = r.u8();
    std::string what;
    wire::read(r, what);
    switch (tag) {
        case t_not_implemented: {
            std::string fn = what;
            if (fn.rfind(ni_prefix, 0) == 0 && fn.size() >= ni_prefix.size() + ni_suffix.size() &&
                fn.compare(fn.size() - ni_suffix.size(), ni_suffix.size(), ni_suffix) == 0)
                fn = fn.substr(ni_prefix.size(), fn.size() - ni_prefix.size() - ni_suffix.size());
            return std::make_exception_ptr(NotImplemented(fn));
        }
        case t_topology: return std::make_exception_ptr(TopologyError(what));
        case t_io: {
            std::string file;
            wire::read(r, file);
            std::uint64_t line = 0;
            wire::read(r, line);
            const std::string head = file + ":" + std::to_string(line) + ": ";
            return std::make_exception_ptr(
                IoError(file, static_cast<std::size_t>(line), what.rfind(head, 0) == 0 ? what.substr(head.size()) : what));
        }
        case t_invalid_argument: return std::make_exception_ptr(std::invalid_argument(what));
        case t_domain: return std::make_exception_ptr(std::domain_error(what));
        case t_length: return std::make_exception_ptr(std::length_error(what));
        case t_out_of_range: return std::make_exception_ptr(std::out_of_range(what));
        case t_logic: return std::make_exception_ptr(std::logic_error(what));
        case t_range: return std::make_exception_ptr(std::range_error(what));
        case t_overflow: return std::make_exception_ptr(std::overflow_error(what));
        case t_underflow: return std::make_exception_ptr(std::underflow_error(what));
        case t_runtime: return std::make_exception_ptr(std::runtime_error(what));
        case t_bad_alloc: return std::make_exception_ptr(std::bad_alloc());
        case t_exception:
        case t_unknown: return std::make_exception_ptr(RecordedException(what));
        default: throw wire::Error(wire::Error::malformed, "an exception of unknown kind " + std::to_string(tag));
    }
}

void record_end() {
    Channel& ch = channel();
    if (ch.mode != Channel::Mode::record) return;
    wire::Writer w;
    w.u32(end_of_test);
    w.u32(ch.calls);
    send(w);
}

std::uint8_t replay_begin(std::uint32_t line, const char* function, std::uint32_t n) {
    Channel& ch = channel();
    wire::Reader& r = *ch.reader;
    const std::string where = "call " + std::to_string(n) + " (" + function + ")";
    if (ch.timed_next) {
        ch.timed_next = false;
        if (ch.go_fd < 0) stop("no_recording", "a timed call needs the running program (no go channel)");
        if (r.ready()) stop("early", "your program sent the answer of " + where + " before the grader let the call start");
        ch.go_time = std::chrono::steady_clock::now();
        ch.timed_seconds = -2;  // timing this call
        if (!write_all(ch.go_fd, reinterpret_cast<const char*>(&n), sizeof n))
            stop("eof", "your program stopped before " + where);
    }
    try {
        if (r.at_end()) stop("eof", "your program stopped in " + where);
        const std::uint32_t got_line = r.u32(), got_n = r.u32();
        if (got_line == end_of_test)
            stop("mismatch", "your program's test ended where the judge made " + where);
        if (got_line != line || got_n != n)
            stop("mismatch", "the recording does not match " + where + ": it holds call " + std::to_string(got_n) +
                                 " of the function on line " + std::to_string(got_line) + " of the lab header");
        const std::uint8_t outcome = r.u8();
        if (outcome > 1) throw wire::Error(wire::Error::malformed, "an outcome byte of " + std::to_string(outcome));
        return outcome;
    } catch (const wire::Error& e) {
        stop(e.kind == wire::Error::truncated ? "eof" : "malformed", std::string(e.what()) + " (" + where + ")");
    }
}

void replay_end() {
    Channel& ch = channel();
    if (ch.timed_seconds == -2)
        ch.timed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - ch.go_time).count();
}

void replay_end_of_test() {
    Channel& ch = channel();
    if (ch.mode != Channel::Mode::replay) return;
    wire::Reader& r = *ch.reader;
    const std::string after = ch.calls ? "after call " + std::to_string(ch.calls) + " (" + ch.last_function + ")"
                                       : std::string("before its first call");
    try {
        if (r.at_end()) stop("eof", "your program stopped " + after + ", before the test ended");
        const std::uint32_t got_line = r.u32(), got_n = r.u32();
        if (got_line != end_of_test || got_n != ch.calls)
            stop("extra", "your program's test made more calls than the judge's (" + after + ")");
    } catch (const wire::Error& e) {
        stop(e.kind == wire::Error::truncated ? "eof" : "malformed", std::string(e.what()) + " (" + after + ")");
    }
}

}  // namespace boundary

double time_student_call(const std::function<void()>& f) {
    boundary::Channel& ch = boundary::channel();
    const auto t0 = std::chrono::steady_clock::now();
    ch.timed_next = ch.mode != boundary::Channel::Mode::off;
    ch.timed_seconds = -1;
    f();
    const double local = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool unused = ch.timed_next;
    ch.timed_next = false;
    // The performer's clock counts for nothing: 0 there keeps its control flow the judge's when the judge's own
    // measurement passes (a test that REQUIREs on the time stops where the judge stops).
    if (ch.mode == boundary::Channel::Mode::record) return 0.0;
    if (ch.mode == boundary::Channel::Mode::off) return local;
    if (unused || ch.timed_seconds < 0)
        boundary::stop("mismatch", "time_student_call: the timed code made no call into the student's code");
    return ch.timed_seconds;
}

}  // namespace geolab
