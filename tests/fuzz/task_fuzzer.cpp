// Task parsing and validation on arbitrary bytes: every input is either a
// task or an InputError naming the offending part; nothing else escapes,
// and a task that parses writes back to JSON that parses to the same task.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include <modsynth/task/input_error.h>
#include <modsynth/task/task_io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace modsynth::task;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Task task;
    try {
        task = parse_task_text(text);
    } catch (const InputError&) {
        return 0;
    }
    // What parsed must survive its own round trip.
    const auto again = to_json(parse_task(to_json(task)));
    if (again != to_json(task)) std::abort();
    return 0;
}
