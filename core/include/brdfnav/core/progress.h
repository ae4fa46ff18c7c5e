// The one shape of progress reports, for every long job: the renderer's passes, the database
// builder's phases and the commands that draw them (the CLI's bars on stderr).
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace brdfnav {

// (phase, done, total): `done` of `total` units of the phase named `phase` ("diffuse pass",
// "render", "blend check", ...) are finished. Called on the thread that started the job, a few
// times a second while it works and once with done == total when a phase ends; a new phase
// starts at a new name. An exception it throws stops the job: the caller's way to drop work
// nobody waits for (each job says what it keeps).
using ProgressSink =
    std::function<void(std::string_view phase, std::size_t done, std::size_t total)>;

}  // namespace brdfnav
