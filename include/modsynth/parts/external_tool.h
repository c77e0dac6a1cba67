#pragma once
// The programs the printed parts are rendered and checked with (Debian's
// openscad and admesh), run with a time limit; their absence is an
// outcome, not an error.
#include <string>
#include <vector>

namespace modsynth::parts {

/// Whether `program` is an executable file in a folder of PATH.
bool on_path(const std::string& program);

struct ToolRun {
    bool started = false;    ///< false: the program could not be run
    bool timed_out = false;  ///< killed at the time limit
    int exit_code = -1;      ///< when it ended by itself
    std::string output;      ///< stdout and stderr together

    bool ok() const { return started && !timed_out && exit_code == 0; }
};

/// Runs argv[0] (looked up in PATH) with the rest as arguments, its output
/// captured, and kills it after `time_limit` seconds.
ToolRun run_tool(const std::vector<std::string>& argv, double time_limit);

/// What admesh says of an STL file.
struct AdmeshReport {
    bool parsed = false;          ///< the report had every figure below
    int parts = 0;                ///< connected shells
    int disconnected_facets = 0;  ///< facets with an edge no other facet shares
    int degenerate_facets = 0;
    int edges_fixed = 0;
    int facets_added = 0;  ///< to fill holes
    int facets_reversed = 0;
    int backwards_edges = 0;

    /// A closed manifold of one piece: one part and nothing admesh had to fix.
    bool closed_manifold() const {
        return parsed && parts == 1 && disconnected_facets == 0 && degenerate_facets == 0 &&
               edges_fixed == 0 && facets_added == 0 && facets_reversed == 0 &&
               backwards_edges == 0;
    }
    /// One line for the build sheet and messages.
    std::string summary() const;
};

/// Reads admesh's report (its "Original" column: the file as written).
AdmeshReport parse_admesh(const std::string& output);

}  // namespace modsynth::parts
