// Binary scene files: our own (oconv's output, FORMAT=radphoton_scene), RADIANCE's
// octrees (the file list, and a frozen octree's tree and object records) and RADIANCE's
// compiled meshes (.rtm), as getinfo, oconv -i, instance and mesh read them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "scene/mesh_file.h"
#include "scene/octree_file.h"
#include "scene/scene_file.h"
#include "util/error.h"
#include "util/header.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    rp::Header header;
    std::string_view rest;
    if (!rp::splitHeader(bytes, header, rest)) return 0;
    const std::string format = header.format();
    auto guarded = [](auto&& read) {
        try {
            read();
        } catch (const rp::InputError&) {
        }
    };
    if (format == rp::kSceneFileFormat) {
        guarded([&] { (void)rp::decodeScene(rest, "fuzz"); });
    } else if (format == rp::kRadianceOctreeFormat) {
        guarded([&] { (void)rp::radianceCube(rest, false, "fuzz"); });
        guarded([&] {
            if (rp::radianceOctreeFiles(rest, "fuzz").empty())
                (void)rp::decodeRadianceFrozenOctree(rest, "fuzz");
        });
        guarded([&] { (void)rp::decodeRadianceOctree(rest, "fuzz"); });  // oconv -i
    } else {
        guarded([&] { (void)rp::radianceCube(rest, true, "fuzz"); });
        guarded([&] { (void)rp::decodeMeshFile(bytes, "fuzz"); });
    }
    return 0;
}
