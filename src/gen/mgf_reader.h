// An MGF 2.0 reader (the Materials and Geometry Format of RADIANCE's mgflib): lines,
// includes, and the contexts every entity leaves behind (colours, materials, vertices,
// object names, transforms with arrays), as RADIANCE's MGF parser keeps them. Surfaces
// go to an MgfHandler; prisms, tori and faces with holes are first rewritten as the
// entities RADIANCE's parser turns them into. What becomes RADIANCE text is mgf2rad.h.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gen/mgf_color.h"
#include "scene/xform.h"
#include "util/error.h"
#include "util/vec.h"

namespace rp::gen {

using MgfArgs = std::vector<std::string>;  // one entity: its name, then its words

// RADIANCE's MG_E* errors, with its messages (mgf_mesg.h).
enum class MgfError {
    UnknownEntity = 1,
    ArgCount,
    ArgType,
    IllegalValue,
    Undefined,
    NoFile,
    IncludeError,
    OutOfMemory,
    Seek,
    BadMaterial,
    LineTooLong,
    ContextClose
};
const char* mgfErrorMessage(MgfError e);

// What a handler throws to reject the entity being handled; the reader adds file and line.
struct MgfFailure {
    MgfError error;
};
[[noreturn]] inline void mgfFail(MgfError e) { throw MgfFailure{e}; }

// Material context (RADIANCE C_MATERIAL, float fields as there). `clock` counts changes
// since a client last reset it: mgf2rad prints a material when it is non-zero.
struct MgfMaterial {
    int clock = 1;
    bool oneSided = false;
    float nr = 1, ni = 0;  // index of refraction
    float rd = 0, td = 0, ed = 0, rs = 0, rsRough = 0, ts = 0, tsRough = 0;
    MgfColor rdColor, tdColor, edColor, rsColor, tsColor;
};

struct MgfVertex {
    Vec3 p, n;  // n is zero or unit length
};

// The surfaces of the format; each receives the entity's words (args[0] its name).
class MgfHandler {
public:
    virtual ~MgfHandler() = default;
    virtual void comment(const MgfArgs& args) = 0;
    virtual void face(const MgfArgs& args) = 0;
    virtual void cone(const MgfArgs& args) = 0;
    virtual void cylinder(const MgfArgs& args) = 0;
    virtual void sphere(const MgfArgs& args) = 0;
    virtual void ring(const MgfArgs& args) = 0;
};

class MgfReader {
public:
    explicit MgfReader(MgfHandler& handler);
    ~MgfReader();

    // Reads a file (includes relative to its folder). Bad input is an InputError naming
    // the file and line where it was found ("a.mgf:7: Undefined reference: f v1 v2 v3").
    void loadFile(const std::string& path);
    // Reads text as if it were the file `name`.
    void loadText(std::string_view text, const std::string& name);

    // Entities whose name the format does not know: skipped and counted, as RADIANCE
    // does (the format asks readers to stay open to later versions); `warnings` has one
    // line "file:line: Unknown entity: NAME" for the first.
    unsigned unknownCount() const { return unknown_; }
    void resetUnknownCount() { unknown_ = 0; }
    const std::vector<std::string>& warnings() const { return warnings_; }

    // For handlers: the named vertex (nullptr if undefined), the current material and its
    // name ("" for the unnamed one), the object name stack.
    const MgfVertex* vertex(const std::string& name) const;
    MgfMaterial& material() { return *material_; }
    const std::string& materialName() const { return materialName_; }
    const std::vector<std::string>& objectNames() const { return objects_; }

    // The current transform (RADIANCE xf_xfmpoint, xf_xfmvect, xf_rotvect, xf_scale) and
    // whether it mirrors (vertex order must then be reversed).
    Vec3 xfPoint(const Vec3& p) const;
    Vec3 xfVector(const Vec3& v) const;
    Vec3 rotVector(const Vec3& v) const;
    double xfScale(double d) const;
    bool reversed() const;

    // Runs one entity as if read from the current line (handlers use it for the
    // entities they expand into).
    void handle(const MgfArgs& args);

private:
    // An open file: its logical lines (backslash-newline joins physical ones) with the
    // number of the last physical line of each, as RADIANCE counts them.
    struct File {
        std::string name;
        int id = 0;
        std::vector<std::string> lines;
        std::vector<int> lineNumbers;
        size_t next = 0;
        int lineNo = 0;
    };

    // One transform context: its own arguments ("-a n" already turned into "-i k"), the
    // array counters, where the array body starts, and the transform of the whole stack.
    struct XfSpec {
        struct Dim {
            int i = 0, n = 0;
            size_t argIndex = 0;  // the "k" word of its "-i k"
        };
        std::vector<std::string> args;
        std::vector<Dim> dims;
        int fileId = 0;
        size_t restartLine = 0;
        Transform xf;
        bool rev = false;
    };

    std::unique_ptr<File> makeFile(std::string_view text, const std::string& name);
    void readFile(std::unique_ptr<File> file);
    void runLines(File& file);
    void include(const MgfArgs& args);
    void colorEntity(const MgfArgs& args);
    void mixEntity(const MgfArgs& args);
    void materialEntity(const MgfArgs& args);
    void materialProperty(const MgfArgs& args);
    void vertexEntity(const MgfArgs& args);
    void vertexProperty(const MgfArgs& args);
    void objectEntity(const MgfArgs& args);
    void xfEntity(const MgfArgs& args);
    void xfPush(const MgfArgs& args);
    void xfPop();
    void computeXf(XfSpec& spec);
    void arrayName(const XfSpec* spec);
    void faceWithHoles(const MgfArgs& args);
    void prism(const MgfArgs& args);
    void torus(const MgfArgs& args);

    MgfHandler& handler_;
    std::vector<File*> files_;  // open files, innermost last
    int nextFileId_ = 0;
    unsigned unknown_ = 0;
    std::vector<std::string> warnings_;

    MgfDither dither_;  // one rand() sequence per reader, as per RADIANCE process
    std::map<std::string, MgfColor> colors_;
    MgfColor unnamedColor_;
    MgfColor* color_ = &unnamedColor_;
    std::map<std::string, MgfMaterial> materials_;
    MgfMaterial unnamedMaterial_;
    MgfMaterial* material_ = &unnamedMaterial_;
    std::string materialName_;
    std::map<std::string, MgfVertex> vertices_;
    MgfVertex unnamedVertex_;
    MgfVertex* vertex_ = &unnamedVertex_;
    std::vector<std::string> objects_;
    std::vector<std::unique_ptr<XfSpec>> xf_;  // transform stack, innermost last
};

// RADIANCE's isflt / isint / isname word checks.
bool mgfIsFloat(const std::string& s);
bool mgfIsInt(const std::string& s);
bool mgfIsName(const std::string& s);
// RADIANCE's normalize(): unit length (first-order near 1), returning the old length.
double mgfNormalize(Vec3& v);

}  // namespace rp::gen
