#include "jobs_option.hpp"

#include <charconv>
#include <system_error>

#include "mdr/error.hpp"

namespace mdr::cli {

unsigned parse_jobs(const std::string& text) {
    unsigned jobs = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, jobs);
    if (text.empty() || error != std::errc() || stop != end || jobs < 1) {
        throw InvalidInput("--jobs", message_text(text), "must be a whole number >= 1 (threads)");
    }
    return jobs;
}

}  // namespace mdr::cli
