#pragma once
//! \file grading/boundary_calls.hpp
//! Record and replay of the calls that cross a lab's grading boundary (docs/architecture.md, "Grading
//! protocol"). Two programs run each graded test:
//!  - the performer (test code + the student's code + the recorder) runs the test; every call the test makes
//!    into the student's code goes through a recorder thunk that calls the student's function and streams, in
//!    call order, what it returned: the return value, every non-const reference or pointer argument after the
//!    call, or the exception it threw (type, message, typed fields);
//!  - the judge (the same test code + the lab's given code + the replayer, no student code) runs the test
//!    again; every such call is answered from the recording, and the judge alone decides the verdict.
//! Only calls made from outside the student's code are recorded (nesting depth 0): the student's own calls to
//! each other are renamed away from the thunks in their objects, and a call that reaches a thunk from inside
//! a student call (student -> given code -> student) runs without being recorded. Tests call boundary
//! functions from one thread.
//!
//! Wire format of one call (native byte order, geolab/grading/wire.hpp):
//!   u32 entry (the line of its GEOLAB_BOUNDARY entry), u32 call number (1, 2, ...), u8 outcome (0 returned,
//!   1 threw), then the return value (returned, non-void) or the exception, then the out-arguments in order.
//! The end of the test is the entry 0xffffffff with the call number of the last call.
//! A timed call (time_student_call, grading/test.hpp) waits for the judge's "go" (u32 call number, on the go
//! pipe) before calling the student's code; the judge times from its go until the whole record has arrived.
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "geolab/boundary.hpp"
#include "geolab/grading/wire.hpp"

namespace geolab::boundary {

inline constexpr std::uint32_t end_of_test = 0xffffffffu;

//! The state of this process's side of the boundary (one per process; tests call from one thread).
struct Channel {
    enum class Mode { off, record, replay };
    Mode mode = Mode::off;
    int data_fd = -1;  //!< record: the recording goes here; replay: it is read from here
    int go_fd = -1;    //!< record: the judge's go arrives here; replay: go is written here (-1: no timing)
    std::unique_ptr<wire::Reader> reader;
    std::uint32_t calls = 0;  //!< depth-0 calls made so far
    int depth = 0;            //!< record: how many recorded calls are running (student code on the stack)
    const char* last_function = "";  //!< the function of the last depth-0 call
    bool timed_next = false;         //!< the next depth-0 call is timed
    double timed_seconds = -1;       //!< replay: the judge's measurement of the last timed call
    std::chrono::steady_clock::time_point go_time;
    //! replay: end the test now with a failure (kind: eof, mismatch, malformed, early, extra, no_recording).
    //! Set by the test main; never returns.
    std::function<void(const std::string& kind, const std::string& message)> stop;
};
Channel& channel();

//! Why and where the replay stopped: ends the judge's test (never returns).
[[noreturn]] void stop(const std::string& kind, const std::string& message);

// ---- the recorder (performer) -------------------------------------------------------------------------------
//! Write one finished record (all of it) to the recording; the judge gone ends this process.
void send(wire::Writer& w);
//! A timed call: block until the judge says go for call n.
void wait_go(std::uint32_t n);
//! The exception being handled, encoded (type tag, message, typed fields).
void write_current_exception(wire::Writer& w);
//! The end of the test, after its last call.
void record_end();

// ---- the replayer (judge) -----------------------------------------------------------------------------------
//! Start call n of `function` (entry line): go if timed, read and check the header; returns the outcome byte.
std::uint8_t replay_begin(std::uint32_t line, const char* function, std::uint32_t n);
//! The whole record has been read (stops the timer of a timed call).
void replay_end();
//! Read an encoded exception (as write_current_exception wrote it) and return it.
std::exception_ptr read_exception(wire::Reader& r);
//! The end of the test: the recording must say so too.
void replay_end_of_test();

template <class F>
using ptr = F*;

template <class A>
constexpr bool is_out_ref = std::is_lvalue_reference_v<A> && !std::is_const_v<std::remove_reference_t<A>>;
template <class A>
constexpr bool is_out_ptr = std::is_pointer_v<A> && !std::is_const_v<std::remove_pointer_t<A>> &&
                            !std::is_function_v<std::remove_pointer_t<A>>;

template <class A>
void write_out(wire::Writer& w, A& a) {
    if constexpr (is_out_ref<A>) {
        wire::write(w, a);
    } else if constexpr (is_out_ptr<A>) {
        w.u8(a != nullptr);
        if (a) wire::write(w, *a);
    }
}
//! An out-argument emptied (a default value), where its type allows: after the memory cap was hit, an endless
//! walk's huge output is no answer and cannot be recorded; the recorded failure is the std::bad_alloc.
template <class A>
void clear_out(A& a) {
    if constexpr (is_out_ref<A> || is_out_ptr<A>) {
        using T = std::remove_cvref_t<std::remove_pointer_t<std::remove_reference_t<A>>>;
        if constexpr (std::is_default_constructible_v<T> && std::is_move_assignable_v<T>) {
            if constexpr (is_out_ref<A>) a = T{};
            else if (a) *a = T{};
        }
    }
}
template <class A>
void read_out(wire::Reader& r, A& a) {
    if constexpr (is_out_ref<A>) {
        wire::read(r, a);
    } else if constexpr (is_out_ptr<A>) {
        const bool present = r.u8() != 0;
        if (present != (a != nullptr)) throw wire::Error(wire::Error::malformed, "an out-pointer that was null");
        if (a) wire::read(r, *a);
    }
}

//! The thunk of one boundary entry: defines the student's function in the performer (recorder) or the judge
//! (replayer); the build renames it to the function's own symbol (cmake/GeolabBoundary.cmake).
template <int Line, class Sig>
struct Thunk;
template <int Line, class R, class... A>
struct Thunk<Line, R(A...)> {
    static_assert(!std::is_reference_v<R>, "boundary functions return values, not references");

    template <R (*Fn)(A...), const char* Name>
    static R record(A... a) {
        Channel& ch = channel();
        if (ch.mode != Channel::Mode::record || ch.depth > 0) return Fn(std::forward<A>(a)...);
        const std::uint32_t n = ++ch.calls;
        ch.last_function = Name;
        if (ch.timed_next) {
            ch.timed_next = false;
            wait_go(n);
        }
        wire::Writer w;
        w.u32(static_cast<std::uint32_t>(Line));
        w.u32(n);
        struct Depth {
            Channel& ch;
            explicit Depth(Channel& c) : ch(c) { ++ch.depth; }
            ~Depth() { --ch.depth; }
        };
        try {
            if constexpr (std::is_void_v<R>) {
                {
                    Depth d(ch);
                    Fn(std::forward<A>(a)...);
                }
                w.u8(0);
                (write_out<A>(w, a), ...);
                send(w);
            } else {
                std::optional<R> r;
                {
                    Depth d(ch);
                    r.emplace(Fn(std::forward<A>(a)...));
                }
                w.u8(0);
                wire::write(w, *r);
                (write_out<A>(w, a), ...);
                send(w);
                return std::move(*r);
            }
        } catch (...) {
            const std::exception_ptr thrown = std::current_exception();
            auto failure = [&] {
                w = wire::Writer{};
                w.u32(static_cast<std::uint32_t>(Line));
                w.u32(n);
                w.u8(1);
                try {
                    std::rethrow_exception(thrown);
                } catch (...) {
                    write_current_exception(w);
                }
                (write_out<A>(w, a), ...);
            };
            try {
                failure();
            } catch (const std::bad_alloc&) {  // the out-arguments are too large to record (the memory cap)
                (clear_out<A>(a), ...);
                failure();
            }
            send(w);
            throw;
        }
    }

    template <R (*Fn)(A...), const char* Name>
    static R replay(A... a) {
        Channel& ch = channel();
        if (ch.mode != Channel::Mode::replay)
            stop("no_recording", std::string("the judge called ") + Name + " without a recording to answer it");
        const std::uint32_t n = ++ch.calls;
        ch.last_function = Name;
        const std::uint8_t outcome = replay_begin(static_cast<std::uint32_t>(Line), Name, n);
        wire::Reader& r = *ch.reader;
        std::exception_ptr thrown;
        [[maybe_unused]] std::conditional_t<std::is_void_v<R>, int, R> value{};
        try {
            if (outcome == 0) {
                if constexpr (!std::is_void_v<R>) wire::read(r, value);
            } else {
                thrown = read_exception(r);
            }
            (read_out<A>(r, a), ...);
        } catch (const wire::Error& e) {
            stop(e.kind == wire::Error::truncated ? "eof" : "malformed",
                 std::string(e.what()) + " (in the answer of call " + std::to_string(n) + ", " + Name + ")");
        }
        replay_end();
        if (thrown) std::rethrow_exception(thrown);
        if constexpr (!std::is_void_v<R>) return value;
    }
};

}  // namespace geolab::boundary

#define GEOLAB_BOUNDARY_CAT2(a, b) a##b
#define GEOLAB_BOUNDARY_CAT(a, b) GEOLAB_BOUNDARY_CAT2(a, b)
#define GEOLAB_BOUNDARY_STR2(x) #x
#define GEOLAB_BOUNDARY_STR(x) GEOLAB_BOUNDARY_STR2(x)

// One entry of a lab's GEOLAB_BOUNDARY list, in the record or replay shim (lib/src/grading/boundary_shim.cpp):
// the student's function (by its declared signature) and its thunk, each as a pointer in a section of its own,
// ".geolab.real.LINE" and ".geolab.thunk.LINE", where the build finds both symbols' names (objdump -r).
#define GEOLAB_BOUNDARY_ENTRY(ROLE, name, ...)                                                                  \
    inline constexpr char GEOLAB_BOUNDARY_CAT(geolab_boundary_name_, __LINE__)[] = #name;                       \
    __attribute__((used, section(".geolab.real." GEOLAB_BOUNDARY_STR(__LINE__))))                               \
    ::geolab::boundary::ptr<__VA_ARGS__> GEOLAB_BOUNDARY_CAT(geolab_boundary_real_, __LINE__) = &name;          \
    __attribute__((used, section(".geolab.thunk." GEOLAB_BOUNDARY_STR(__LINE__))))                              \
    ::geolab::boundary::ptr<__VA_ARGS__> GEOLAB_BOUNDARY_CAT(geolab_boundary_thunk_, __LINE__) =                \
        &::geolab::boundary::Thunk<__LINE__, __VA_ARGS__>::template ROLE<&name,                                 \
                                                                         GEOLAB_BOUNDARY_CAT(geolab_boundary_name_, __LINE__)>;
