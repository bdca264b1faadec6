// mkillum's pass over its input (RADIANCE mkillum.c filter, xoptions, xobject): comments
// are copied, `#@mkillum` lines change the settings, "!command" output is read in
// place, and every primitive is copied in RADIANCE mkillum's layout unless the settings
// select it: then polygons, spheres and rings become illum (or light) sources with
// sampled distributions. The command line and the renderer are mkillum.h.
#pragma once

#include <cstdint>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "illum/illum_input.h"
#include "illum/illum_sample.h"
#include "illum/illum_settings.h"
#include "scene/reader.h"

namespace rp::illum {

class IllumFilter {
public:
    // `header`: the command line RADIANCE mkillum records ("mkillum -ab 1 scene.oct"),
    // written with "#@mkillum !" before the first setting line or primitive of each
    // output. `directory`: where data files go ("" the current folder). `commands`: may
    // run "!command"s itself (gen::runBuiltinCommand); the others go to /bin/sh.
    IllumFilter(const IllumTracer& tracer, std::ostream& out, std::string header,
                std::string directory = {}, CommandHook commands = {});
    ~IllumFilter();

    // Processes one input's text; `name` is how messages name it.
    void process(std::string_view text, const std::string& name);

    const IllumSettings& settings() const { return settings_; }

private:
    void process(std::string_view text, const std::string& name, int depth);
    void comment(const std::string& line, const SourceLoc& loc);
    void command(const std::string& command, const SourceLoc& loc, int depth);
    void object(const InputObject& o);
    // The conversions; each returns false when the surface is to be copied as it is.
    bool convertFace(const InputObject& o);
    bool convertRing(const InputObject& o);
    bool convertSphere(const InputObject& o);
    // Writes the illum for distribution `d` (or copies `o` if it is too dark).
    void finish(const InputObject& o, const Distribution& d, const FlatFrame* frame);
    void copy(const InputObject& o);
    void checkHeader();
    std::ostream& out() { return file_ ? *file_ : out_; }

    const IllumTracer& tracer_;
    std::ostream& out_;
    std::unique_ptr<std::ofstream> file_;  // after o=file
    std::string header_;
    std::string directory_;
    CommandHook commands_;
    IllumSettings settings_;
    bool headerDone_ = false;
    uint64_t nextRay_ = 0;  // ray indices: surfaces take consecutive blocks
};

}  // namespace rp::illum
