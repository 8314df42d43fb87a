#pragma once
// Shared by the fuzz harnesses: splitting one fuzz input into a sequence of steps, and the check that turns
// a broken invariant into a finding (abort, which libFuzzer and the replay test both report).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string_view>

#include "protocols/common/Log.h"

namespace ocu::fuzz {

// Log lines are still formatted (that code is under test too) but not printed: millions of inputs. Called at
// the top of every harness (not from a static initialiser: the sink is a global of another file).
inline void quietLogs() {
    static const bool once = (setLogSink([](LogLevel, std::string_view, std::string_view) {}), true);
    (void)once;
}

// A finding: prints what broke and aborts.
[[noreturn]] inline void fail(const char* what) {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
    std::abort();
}
#define OCU_FUZZ_CHECK(cond)                                                                                 \
    do {                                                                                                     \
        if (!(cond))                                                                                         \
            ::ocu::fuzz::fail(#cond);                                                                        \
    } while (0)

// Binary steps: [op u8][length u16 LE][length bytes]..., the last one cut short by the end of the input.
// Keeps stateful harnesses (a station fed datagrams and Beats) mutable by libFuzzer without a grammar.
class Steps {
public:
    Steps(const std::uint8_t* data, std::size_t size) : m_data(data, size) {}
    bool next(std::uint8_t& op, std::span<const std::uint8_t>& body) {
        if (m_pos >= m_data.size())
            return false;
        op = m_data[m_pos++];
        std::size_t len = 0;
        if (m_pos + 2 <= m_data.size()) {
            len = std::size_t(m_data[m_pos]) | (std::size_t(m_data[m_pos + 1]) << 8);
            m_pos += 2;
        } else {
            m_pos = m_data.size();
        }
        if (len > m_data.size() - m_pos)
            len = m_data.size() - m_pos;
        body = m_data.subspan(m_pos, len);
        m_pos += len;
        return true;
    }

private:
    std::span<const std::uint8_t> m_data;
    std::size_t m_pos = 0;
};

// Text steps: one per line ('\n'; a JSON frame holds no raw newline inside a string).
class Lines {
public:
    Lines(const std::uint8_t* data, std::size_t size)
        : m_text(reinterpret_cast<const char*>(data), data ? size : 0) {}
    bool next(std::string_view& line) {
        if (m_pos > m_text.size() || (m_pos == m_text.size() && m_pos != 0))
            return false;
        std::size_t end = m_text.find('\n', m_pos);
        if (end == std::string_view::npos)
            end = m_text.size();
        line = m_text.substr(m_pos, end - m_pos);
        m_pos = end + 1;
        return true;
    }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
};

} // namespace ocu::fuzz
