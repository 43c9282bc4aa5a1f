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
//!   u32 entry (the line of its GEOLAB_BOUNDARY entry), u32 call number (1, 2, ...), one u64 digest per argument
//!   as the test passed it (the object first for a member function; the judge compares its own), the callback
//!   events of the call in order (see "callbacks" below), u8 outcome (0 returned, 1 threw), then the return value
//!   (returned, non-void) or the exception, then the out-arguments in order (for a non-const member function,
//!   the object first).
//! The end of the test is the entry 0xffffffff with the call number of the last call.
//! A timed call (time_student_call, grading/test.hpp) waits for the judge's "go" (u32 call number, on the go
//! pipe) before calling the student's code; the judge times from its go until the whole record has arrived.
#include <chrono>
#include <concepts>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/field.hpp"
#include "geolab/grading/wire.hpp"
#include "geolab/render/image.hpp"
#include "geolab/soup.hpp"

namespace geolab::boundary {
struct CallContext;
//! The field a pointer names, as its source index in the current call (wire.hpp's codec for `const
//! ScalarField*`, e.g. lab 09's Octree::field): 0 null, k + 1 the call's source k (its original or its stand-in).
std::uint32_t field_index(const ScalarField* f);
//! Judge: the field of source index k (0: null); a pointer to none of the call's fields is a malformed answer.
const ScalarField* field_at(std::uint32_t k);
}  // namespace geolab::boundary

namespace geolab::wire {
template <>
struct Codec<const ScalarField*> {
    static constexpr std::size_t min_bytes = 4;
    static void write(Writer& w, const ScalarField* f) { w.u32(boundary::field_index(f)); }
    static void read(Reader& r, const ScalarField*& f) { f = boundary::field_at(r.u32()); }
};
}  // namespace geolab::wire

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
    const char* last_function = "";  //!< the function of the last depth-0 call (off: of the last call a test made)
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
//! Start call n of `function` (entry line): go if timed, read and check the header (entry and call number).
void replay_begin(std::uint32_t line, const char* function, std::uint32_t n);
//! The whole record has been read (stops the timer of a timed call).
void replay_end();
//! Read an encoded exception (as write_current_exception wrote it) and return it.
std::exception_ptr read_exception(wire::Reader& r);
//! The end of the test: the recording must say so too.
void replay_end_of_test();

// ---- callbacks: the fields and functions a student's code calls back ----------------------------------------
// A call's *sources*, numbered in argument order: each `const ScalarField&` argument, each function-reference
// argument (a class passed by value that is callable as double(double), e.g. lab 09's FunctionRef), and the
// `field` member (a `const ScalarField*`) of each argument that has one (lab 09's Octree). The performer passes
// the student's code a recording stand-in for each source; each callback the student's code makes during the
// call (value, gradient, bounds, lipschitz, sign_may_jump; a function's call) is streamed inside the call's
// record as an event: tag 2, source, method, arguments, then 0 and the result, or 1 if it threw. The judge calls
// its own source (the test's object) with the same arguments, in the same order, and requires the same result:
// state the test keeps in its callbacks (an evaluation counter) is the judge's own, and a field answer the
// student's process altered fails the test.

//! A source of callbacks in the current call.
struct Source {
    const ScalarField* field = nullptr;         //!< a field (the original)
    const void* stand_in = nullptr;             //!< performer: what the student's code was given instead
    std::function<double(double)> function;     //!< a function reference (judge: the test's own)
    bool is_function = false;
};
//! The boundary call being recorded or replayed (channel().call; null between calls).
struct CallContext {
    std::vector<Source> sources;
    wire::Writer* events = nullptr;  //!< performer: the call's record, where events go
    std::uint32_t call = 0;
    const char* function = "";
};
//! The current call (performer and judge); null outside boundary calls.
CallContext*& current_call();

enum Method : std::uint8_t { m_value, m_gradient, m_bounds, m_lipschitz, m_sign_may_jump, m_call };
inline constexpr std::uint8_t event_tag = 2;

//! Performer: the stand-in for a field source: forwards every call, records it as an event of the current call.
class RecordingField final : public ScalarField {
public:
    RecordingField(const ScalarField& f, std::uint8_t source) : f_(f), source_(source) {}
    double value(const glm::dvec3& p) const override;
    glm::dvec3 gradient(const glm::dvec3& p) const override;
    Box bounds() const override;
    double lipschitz() const override;
    bool sign_may_jump() const override;

private:
    const ScalarField& f_;
    std::uint8_t source_;
};
//! Performer: a function source's call, recorded.
double record_function_call(const std::function<double(double)>& f, std::uint8_t source, double t);
//! Performer: send what the record holds so far when it is large (events stream during long calls).
void flush_events(wire::Writer& w);
//! Judge: read and replay events until the outcome byte of call n; returns the outcome (0 returned, 1 threw).
std::uint8_t replay_events(wire::Reader& r);

template <class A>
constexpr bool is_field_arg = std::is_same_v<A, const ScalarField&>;
template <class A>
constexpr bool is_function_arg = std::is_class_v<A> && !std::is_reference_v<A> &&
                                 !std::is_base_of_v<ScalarField, A> && std::is_invocable_r_v<double, const A&, double>;
template <class T>
constexpr bool has_field_member = requires(T& t) {
    { t.field } -> std::same_as<const ScalarField*&>;
};
template <class A>
constexpr bool is_holder_arg = std::is_reference_v<A> && has_field_member<std::remove_cvref_t<A>>;

template <class A>
void collect_source(CallContext& c, A& a) {
    if constexpr (is_field_arg<A>) {
        c.sources.push_back({&a, nullptr, {}, false});
    } else if constexpr (is_function_arg<A>) {
        Source s;
        s.is_function = true;
        s.function = [&a](double t) { return double(a(t)); };
        c.sources.push_back(std::move(s));
    } else if constexpr (is_holder_arg<A>) {
        c.sources.push_back({a.field, nullptr, {}, false});
    }
}

//! Performer: what the student's code gets for argument a (a stand-in for a source; else a itself).
struct StandIns {
    std::deque<RecordingField> fields;
    std::deque<std::function<double(double)>> functions;
    std::vector<std::pair<const ScalarField**, const ScalarField*>> restore;  //!< holders' fields to put back
    std::size_t next = 0;                                                      //!< next source index
};
template <class A>
A stand_in(CallContext& c, StandIns& s, A& a) {
    if constexpr (is_field_arg<A>) {
        const std::uint8_t k = static_cast<std::uint8_t>(s.next++);
        const RecordingField& r = s.fields.emplace_back(a, k);
        c.sources[k].stand_in = &r;
        return r;
    } else if constexpr (is_function_arg<A>) {
        const std::uint8_t k = static_cast<std::uint8_t>(s.next++);
        const std::function<double(double)>& f = s.functions.emplace_back(
            [&c, k](double t) { return record_function_call(c.sources[k].function, k, t); });
        c.sources[k].stand_in = &f;
        return A(f);
    } else if constexpr (is_holder_arg<A>) {
        const std::uint8_t k = static_cast<std::uint8_t>(s.next++);
        if (a.field) {
            const RecordingField& r = s.fields.emplace_back(*a.field, k);
            c.sources[k].stand_in = &r;
            auto& slot = const_cast<const ScalarField*&>(a.field);
            s.restore.push_back({&slot, a.field});
            slot = &r;
        }
        return static_cast<A>(a);
    } else {
        return static_cast<A>(a);
    }
}
//! Performer: a value the student's code returned or filled may hold a stand-in (an Octree's field): the
//! test gets the original back.
template <class T>
void restore_fields(const CallContext& c, T& v) {
    if constexpr (has_field_member<T>) {
        for (const Source& s : c.sources)
            if (s.stand_in && v.field == s.stand_in) v.field = s.field;
    }
}

template <class A>
constexpr bool is_out_ref = std::is_lvalue_reference_v<A> && !std::is_const_v<std::remove_reference_t<A>>;
template <class A>
constexpr bool is_out_ptr = std::is_pointer_v<A> && !std::is_const_v<std::remove_pointer_t<A>> &&
                            !std::is_function_v<std::remove_pointer_t<A>>;

// ---- arguments --------------------------------------------------------------------------------------------
//! A cheap stand-in for an argument's content: its scalars and, for each vector or string, where its elements are,
//! how many, and a sample of them (all of a short one, else 64 evenly spaced and the last), so that a buffer freed
//! and reused at the same address by an object of the same size but other content (a test's temporaries) gets
//! another key. False when the type has parts this cannot summarise.
template <class T>
bool shallow(wire::Writer& w, const T& v) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T> || wire::is_blob<T>) {
        w.bytes(&v, sizeof v);
        return true;
    } else if constexpr (requires { typename T::value_type; v.data(); v.size(); }) {
        const void* d = v.data();
        w.bytes(&d, sizeof d);
        const std::size_t n = v.size();
        w.u64(n);
        using E = std::remove_cvref_t<decltype(*v.data())>;
        auto sample = [&](std::size_t i) {
            if constexpr (std::is_trivially_copyable_v<E>)
                w.bytes(&v.data()[i], sizeof(E));
            else
                shallow(w, v.data()[i]);  // what it can summarise of an element (deterministic either way)
        };
        const std::size_t step = n <= 64 ? 1 : n / 64;
        for (std::size_t i = 0; i < n; i += step) sample(i);
        if (n > 0) sample(n - 1);
        return true;
    } else if constexpr (requires { v.geolab_fields(); }) {
        bool ok = true;
        std::apply([&](const auto&... x) { ((ok = ok && shallow(w, x)), ...); }, v.geolab_fields());
        return ok;
    } else {
        return false;
    }
}
//! Digests of large arguments by their shallow summary (a test calls valence(mesh, v) for every vertex: the mesh is
//! encoded once, not once a call). An element changed in place between two calls keeps its old digest, in the
//! performer and the judge alike, unless it is one of the sampled ones.
std::uint64_t* memo_digest(const std::string& shallow_key);
void memo_store(const std::string& shallow_key, std::uint64_t digest);
//! Forget every memoised digest.
void memo_clear();
//! Forget the digests memoised under these keys (after each call that changes an argument, the keys of its
//! out-arguments before and after the call: both processes at the same point).
void memo_forget(const std::vector<std::string>& shallow_keys);

//! The memo key of an object: its type and its shallow summary; empty when shallow() cannot summarise it.
template <class T>
std::string shallow_key(const T& v) {
    wire::Writer k;
    const std::string_view type = typeid(T).name();
    k.bytes(type.data(), type.size());
    return shallow(k, v) ? std::move(k.buffer()) : std::string();
}

//! A 64-bit digest of an input argument as encoded on the wire (0 for callbacks, which are not values). The
//! performer records one per argument; the judge requires its own arguments to give the same digests.
template <class A>
std::uint64_t arg_digest(A& a) {
    using T = std::remove_cvref_t<A>;
    if constexpr (is_field_arg<A> || is_function_arg<T>) {
        return 0;
    } else {
        wire::Writer w;
        if constexpr (is_out_ptr<T>) {
            return a ? 3 : 1;  // an out-pointer: only whether there is one (its target may be uninitialised)
        } else if constexpr (std::is_pointer_v<T>) {
            w.u8(a != nullptr);
            if (a) wire::write(w, *a);
            return std::hash<std::string_view>{}(w.buffer()) | 1;  // never 0
        } else {
            std::string key;
            if constexpr (std::is_class_v<T> && std::is_reference_v<A>) {
                key = shallow_key<T>(a);
                if (!key.empty())
                    if (const std::uint64_t* d = memo_digest(key)) return *d;
            }
            wire::write(w, a);
            const std::uint64_t d = std::hash<std::string_view>{}(w.buffer()) | 1;
            if (!key.empty() && w.buffer().size() >= 4096) memo_store(key, d);
            return d;
        }
    }
}
//! Appends the shallow key (as arg_digest makes it) of an out-argument's object: the digest memoised under it may
//! be out of date once the call has changed the object.
template <class A>
void out_key(std::vector<std::string>& keys, A& a) {
    if constexpr (is_out_ref<A> || is_out_ptr<A>) {
        using T = std::remove_cvref_t<std::remove_pointer_t<std::remove_reference_t<A>>>;
        if constexpr (std::is_class_v<T>) {
            const T* obj = nullptr;
            if constexpr (is_out_ptr<A>) obj = a;
            else obj = &a;
            if (!obj) return;
            if (std::string k = shallow_key<T>(*obj); !k.empty()) keys.push_back(std::move(k));
        }
    }
}
//! Judge: the arguments differ from the recorded ones (argument index from 1; 0 is the object of a member).
[[noreturn]] void argument_mismatch(std::size_t index, bool member);


// ---- answers the judge may use: invariants its code relies on ------------------------------------------------
// The judge's standard library checks every index into a container (_GLIBCXX_ASSERTIONS), but some accessors that
// tests call on an answer compute addresses themselves: PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]),
// render::Image::pixel() reads rgba at 4·(y·width + x), and lib code (built without the assertions) indexes a
// soup's positions by its indices. A hostile answer there would make the judge read memory outside the answer.
// So every answer is checked as it is read, through its fields, vectors, optionals, pairs, tuples and arrays; one
// that breaks such an invariant is a malformed answer (the test fails, naming the problem).

//! Why `s` cannot be a polygon soup (empty: it can): offsets must start at 0, never decrease and end at the number
//! of indices; every index must name a position.
std::string soup_problem(const PolygonSoup& s);
//! Why `img` cannot be an image (empty: it can): width, height ≥ 0 and rgba.size() = 4 · width · height.
std::string image_problem(const render::Image& img);

template <class T>
struct is_std_vector : std::false_type {};
template <class T, class A>
struct is_std_vector<std::vector<T, A>> : std::true_type {};
template <class T>
struct is_std_optional : std::false_type {};
template <class T>
struct is_std_optional<std::optional<T>> : std::true_type {};
template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};
template <class T>
struct is_pair_or_tuple : std::false_type {};
template <class A, class B>
struct is_pair_or_tuple<std::pair<A, B>> : std::true_type {};
template <class... A>
struct is_pair_or_tuple<std::tuple<A...>> : std::true_type {};

//! Whether a T may hold a soup or an image (the only types with such invariants): the others are not walked.
template <class T>
constexpr bool may_break();
template <class Tuple, std::size_t... I>
constexpr bool any_may_break(std::index_sequence<I...>) {
    return (false || ... || may_break<std::remove_cvref_t<std::tuple_element_t<I, Tuple>>>());
}
template <class T>
constexpr bool may_break() {
    if constexpr (std::is_same_v<T, PolygonSoup> || std::is_same_v<T, render::Image>) {
        return true;
    } else if constexpr (is_std_vector<T>::value || is_std_array<T>::value || is_std_optional<T>::value) {
        return may_break<typename T::value_type>();
    } else if constexpr (is_pair_or_tuple<T>::value) {
        return any_may_break<T>(std::make_index_sequence<std::tuple_size_v<T>>{});
    } else if constexpr (requires(const T& v) { v.geolab_fields(); }) {
        using Fields = decltype(std::declval<const T&>().geolab_fields());
        return any_may_break<Fields>(std::make_index_sequence<std::tuple_size_v<Fields>>{});
    } else {
        return false;
    }
}

//! The first broken invariant in an answer read from the recording (see above), or "".
template <class T>
std::string answer_problem(const T& v) {
    if constexpr (!may_break<T>()) {
        return "";
    } else if constexpr (std::is_same_v<T, PolygonSoup>) {
        return soup_problem(v);
    } else if constexpr (std::is_same_v<T, render::Image>) {
        return image_problem(v);
    } else if constexpr (is_std_vector<T>::value || is_std_array<T>::value) {
        using E = typename T::value_type;
        if constexpr (std::is_class_v<E> && !std::is_same_v<E, std::string>)
            for (const auto& x : v)
                if (std::string why = answer_problem(x); !why.empty()) return why;
        return "";
    } else if constexpr (is_std_optional<T>::value) {
        return v ? answer_problem(*v) : std::string();
    } else if constexpr (is_pair_or_tuple<T>::value) {
        std::string why;
        std::apply([&](const auto&... x) { ((why.empty() ? (void)(why = answer_problem(x)) : (void)0), ...); }, v);
        return why;
    } else if constexpr (requires { v.geolab_fields(); }) {
        std::string why;
        std::apply([&](const auto&... x) { ((why.empty() ? (void)(why = answer_problem(x)) : (void)0), ...); },
                   v.geolab_fields());
        return why;
    } else {
        return "";
    }
}
//! Judge: reads an answer and checks it (a broken invariant is a malformed recording).
template <class T>
void read_answer(wire::Reader& r, T& v) {
    wire::read(r, v);
    if (std::string why = answer_problem(v); !why.empty()) r.fail("an answer that breaks its type's invariants: " + why);
}

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
        read_answer(r, a);
    } else if constexpr (is_out_ptr<A>) {
        const bool present = r.u8() != 0;
        if (present != (a != nullptr)) throw wire::Error(wire::Error::malformed, "an out-pointer that was null");
        if (a) read_answer(r, *a);
    }
}
template <class A>
void restore_out(const CallContext& c, A& a) {
    if constexpr (is_out_ref<A>) {
        restore_fields(c, a);
    } else if constexpr (is_out_ptr<A>) {
        if (a) restore_fields(c, *a);
    }
}

//! Record and replay of one boundary entry with parameters P... (for a member function, P starts with the
//! object: `C&` or `const C&`). `Member`: the first parameter is the object.
template <int Line, bool Member, class R, class... P>
struct Impl {
    static_assert(!std::is_reference_v<R>, "boundary functions return values, not references");

    template <class Invoke>
    static R record(const char* name, Invoke&& invoke, P... p) {
        Channel& ch = channel();
        if (ch.mode != Channel::Mode::record || ch.depth > 0) {
            if (ch.mode == Channel::Mode::off) ch.last_function = name;  // the test's last call (the course's own runs)
            return invoke(std::forward<P>(p)...);
        }
        const std::uint32_t n = ++ch.calls;
        ch.last_function = name;
        if (ch.timed_next) {
            ch.timed_next = false;
            wait_go(n);
        }
        CallContext c;
        c.call = n;
        c.function = name;
        (collect_source<P>(c, p), ...);
        wire::Writer w;
        c.events = &w;
        w.u32(static_cast<std::uint32_t>(Line));
        w.u32(n);
        {
            CallContext* outer = std::exchange(current_call(), &c);
            (w.u64(arg_digest<P>(p)), ...);
            current_call() = outer;
        }
        std::vector<std::string> out_keys;  // the out-arguments' memo keys, before the call and after it
        (out_key<P>(out_keys, p), ...);
        struct Scope {
            Channel& ch;
            CallContext& c;
            CallContext* outer;
            Scope(Channel& h, CallContext& cc) : ch(h), c(cc), outer(current_call()) {
                ++ch.depth;
                current_call() = &c;
            }
            ~Scope() {
                --ch.depth;
                current_call() = outer;
            }
        };
        StandIns s;
        bool finished = false;
        std::size_t answer_at = std::string::npos;  // where the answer starts in w, once the call has returned
        auto finish = [&] {
            if (std::exchange(finished, true)) return;
            for (auto& [slot, original] : s.restore)
                for (const Source& src : c.sources)
                    if (src.stand_in && *slot == src.stand_in) *slot = original;
            (restore_out<P>(c, p), ...);
            if constexpr (((is_out_ref<P> || is_out_ptr<P>) || ...)) {
                (out_key<P>(out_keys, p), ...);
                memo_forget(out_keys);
            }
        };
        try {
            if constexpr (std::is_void_v<R>) {
                {
                    Scope d(ch, c);
                    std::tuple<P...> args{stand_in<P>(c, s, p)...};
                    std::apply(invoke, std::move(args));
                }
                finish();
                CallContext* outer = std::exchange(current_call(), &c);
                answer_at = w.buffer().size();
                w.u8(0);
                (write_out<P>(w, p), ...);
                current_call() = outer;
                send(w);
            } else {
                std::optional<R> r;
                {
                    Scope d(ch, c);
                    std::tuple<P...> args{stand_in<P>(c, s, p)...};
                    r.emplace(std::apply(invoke, std::move(args)));
                }
                finish();
                restore_fields(c, *r);
                CallContext* outer = std::exchange(current_call(), &c);
                answer_at = w.buffer().size();
                w.u8(0);
                wire::write(w, *r);
                (write_out<P>(w, p), ...);
                current_call() = outer;
                send(w);
                return std::move(*r);
            }
        } catch (...) {
            finish();
            // a failure while the answer was being written (the memory cap, recording a huge out-argument):
            // drop the partial answer and record the failure instead
            if (answer_at != std::string::npos) w.buffer().resize(answer_at);
            const std::exception_ptr thrown = std::current_exception();
            CallContext* outer = std::exchange(current_call(), &c);
            const std::size_t failure_at = w.buffer().size();
            auto failure = [&] {
                w.buffer().resize(failure_at);
                w.u8(1);
                try {
                    std::rethrow_exception(thrown);
                } catch (...) {
                    write_current_exception(w);
                }
                (write_out<P>(w, p), ...);
            };
            try {
                failure();
            } catch (const std::bad_alloc&) {  // the out-arguments are too large to record (the memory cap)
                (clear_out<P>(p), ...);
                failure();
            }
            current_call() = outer;
            send(w);
            throw;
        }
    }

    static R replay(const char* name, P... p) {
        Channel& ch = channel();
        if (ch.mode != Channel::Mode::replay)
            stop("no_recording", std::string("the judge called ") + name + " without a recording to answer it");
        const std::uint32_t n = ++ch.calls;
        ch.last_function = name;
        CallContext c;
        c.call = n;
        c.function = name;
        (collect_source<P>(c, p), ...);
        CallContext* outer = std::exchange(current_call(), &c);
        struct Back {
            CallContext* outer;
            ~Back() { current_call() = outer; }
        } back{outer};
        replay_begin(static_cast<std::uint32_t>(Line), name, n);
        wire::Reader& r = *ch.reader;
        std::exception_ptr thrown;
        [[maybe_unused]] std::conditional_t<std::is_void_v<R>, int, R> value{};
        try {
            std::size_t index = 0;
            auto check = [&](std::uint64_t mine) {
                const std::uint64_t got = r.u64();
                if (got != mine) argument_mismatch(Member ? index : index + 1, Member);
                ++index;
            };
            (check(arg_digest<P>(p)), ...);
            std::vector<std::string> out_keys;  // as the performer: before the call and after it
            (out_key<P>(out_keys, p), ...);
            const std::uint8_t outcome = replay_events(r);
            if (outcome == 0) {
                if constexpr (!std::is_void_v<R>) read_answer(r, value);
            } else {
                thrown = read_exception(r);
            }
            (read_out<P>(r, p), ...);
            if constexpr (((is_out_ref<P> || is_out_ptr<P>) || ...)) {
                (out_key<P>(out_keys, p), ...);
                memo_forget(out_keys);
            }
        } catch (const wire::Error& e) {
            stop(e.kind == wire::Error::truncated ? "eof" : "malformed",
                 std::string(e.what()) + " (in the answer of call " + std::to_string(n) + ", " + name + ")");
        }
        replay_end();
        if (thrown) std::rethrow_exception(thrown);
        if constexpr (!std::is_void_v<R>) return value;
    }
};

//! The types of one entry's two pointers: the student's function (a function pointer, or a pointer to member)
//! and its thunk (always a plain function: for a member, the object comes first, as the ABI passes `this`).
template <class Sig>
struct Entry;
template <class R, class... A>
struct Entry<R(A...)> {
    using real = R (*)(A...);
    using thunk = R (*)(A...);
};
template <class R, class C, class... A>
struct Entry<R (C::*)(A...)> {
    using real = R (C::*)(A...);
    using thunk = R (*)(C*, A...);
};
template <class R, class C, class... A>
struct Entry<R (C::*)(A...) const> {
    using real = R (C::*)(A...) const;
    using thunk = R (*)(const C*, A...);
};

//! The thunk of one boundary entry: defines the student's function in the performer (recorder) or the judge
//! (replayer); the build renames it to the function's own symbol (cmake/GeolabBoundary.cmake).
template <int Line, class Sig>
struct Thunk;
template <int Line, class R, class... A>
struct Thunk<Line, R(A...)> {
    template <R (*Fn)(A...), const char* Name>
    static R record(A... a) {
        return Impl<Line, false, R, A...>::record(
            Name, [](A... x) -> R { return Fn(std::forward<A>(x)...); }, std::forward<A>(a)...);
    }
    template <R (*Fn)(A...), const char* Name>
    static R replay(A... a) {
        return Impl<Line, false, R, A...>::replay(Name, std::forward<A>(a)...);
    }
};
template <int Line, class R, class C, class... A>
struct Thunk<Line, R (C::*)(A...)> {
    template <R (C::*Fn)(A...), const char* Name>
    static R record(C* self, A... a) {
        return Impl<Line, true, R, C&, A...>::record(
            Name, [](C& o, A... x) -> R { return (o.*Fn)(std::forward<A>(x)...); }, *self, std::forward<A>(a)...);
    }
    template <R (C::*Fn)(A...), const char* Name>
    static R replay(C* self, A... a) {
        return Impl<Line, true, R, C&, A...>::replay(Name, *self, std::forward<A>(a)...);
    }
};
template <int Line, class R, class C, class... A>
struct Thunk<Line, R (C::*)(A...) const> {
    template <R (C::*Fn)(A...) const, const char* Name>
    static R record(const C* self, A... a) {
        return Impl<Line, true, R, const C&, A...>::record(
            Name, [](const C& o, A... x) -> R { return (o.*Fn)(std::forward<A>(x)...); }, *self,
            std::forward<A>(a)...);
    }
    template <R (C::*Fn)(A...) const, const char* Name>
    static R replay(const C* self, A... a) {
        return Impl<Line, true, R, const C&, A...>::replay(Name, *self, std::forward<A>(a)...);
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
    ::geolab::boundary::Entry<__VA_ARGS__>::real GEOLAB_BOUNDARY_CAT(geolab_boundary_real_, __LINE__) = &name;  \
    __attribute__((used, section(".geolab.thunk." GEOLAB_BOUNDARY_STR(__LINE__))))                              \
    ::geolab::boundary::Entry<__VA_ARGS__>::thunk GEOLAB_BOUNDARY_CAT(geolab_boundary_thunk_, __LINE__) =      \
        &::geolab::boundary::Thunk<__LINE__, __VA_ARGS__>::template ROLE<&name,                                 \
                                                                         GEOLAB_BOUNDARY_CAT(geolab_boundary_name_, __LINE__)>;
