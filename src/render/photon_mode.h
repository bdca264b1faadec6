// RADIANCE's photon-map mode rules for the backward pass, one named predicate per rule
// (pmapmat.h ambRayInPmap and shadowRayInPmap, pmapamb.c, pmapray.c, source.c), so that
// the shading loop asks instead of knowing them. Built from which maps are loaded
// (PhotonLighting::kinds) and the -ab the user gave.
#pragma once

namespace rp::render {

// The kinds of photon maps given with -ap.
struct PhotonMapKinds {
    bool global = false;  // global or precomputed global
    bool caustic = false;
    bool direct = false;
    bool volume = false;
    bool contrib = false;
    bool contribCaustic = false;  // a contribution map holding caustic photons
    bool any() const { return global || caustic || direct || volume || contrib; }
};

// Where on its path a ray is: ambient bounces so far and reflections so far (RADIANCE
// rlvl), the two things the rules look at.
struct PathDepth {
    int ambientLevel = 0;
    int depth = 0;
};

class PhotonMode {
public:
    PhotonMode(const PhotonMapKinds& maps, int requestedBounces);

    bool active() const { return active_; }
    const PhotonMapKinds& maps() const { return maps_; }

    // Manual 5.1, RADIANCE 5.4's rtrace/rpict: with photon maps the ambient calculation
    // makes one bounce (final gather) whose sample hits read the global map; any -ab >= 0
    // acts as 1 (5.4 raises 0 too); a negative -ab reads the map at the primary hit.
    int ambientBounces() const { return bounces_; }
    // RADIANCE source.c: no virtual sources in photon-map mode; light relayed by mirrors
    // and prisms arrives through caustic photons.
    bool virtualSources() const { return !active(); }
    // Caustic light at the hits of non-ambient rays: a caustic map's, or a contribution
    // map's caustic photons (pmapamb.c ambPmapCaustic).
    bool causticLight() const { return maps_.caustic || maps_.contribCaustic; }

    // pmapmat.h ambRayInPmap: an ambient ray's specular children are not traced where the
    // photons already carry what they would find: with -ab < 0, below the first gather
    // bounce, or whenever caustic light is in the photons. With a global map alone a
    // final-gather ray does see through glass and mirrors (daylight README: the sky
    // through the window, otherwise missing from the work plane).
    bool specularRaysInPhotons(const PathDepth& p) const {
        return active() && p.ambientLevel > 0 && (bounces_ < 0 || p.depth > 1 || causticLight());
    }
    // ambRayInPmap for a BSDF's specular direct light: in the photons only below the
    // first gather bounce (rlvl > 1); at a final-gather hit the light a BSDF window sends
    // straight to the gathering point is not (issue 43: sensors beside a Klems window read
    // half of RADIANCE's).
    bool specularDirectInPhotons(const PathDepth& p) const {
        return active() && p.ambientLevel > 0 && (bounces_ < 0 || p.depth > 1);
    }
    // pmapmat.h shadowRayInPmap: a shadow ray is stopped by transparent surfaces (glass,
    // trans, mirrors, BSDFs) where the photons carry the light they pass: with -ab < 0,
    // below an ambient ray, or on the primary path when caustic light is in the photons.
    bool shadowsStopAtTransparent(const PathDepth& p) const {
        return active() && (bounces_ < 0 || p.ambientLevel > 0 || causticLight());
    }
    // Manual 5.4: direct photons replace the direct calculation (a debugging aid).
    bool directFromPhotons() const { return maps_.direct; }
    // Light scattered out of a shadow ray by a medium reaches surfaces as global photons:
    // shadow rays then lose the whole extinction, not only the absorbed part.
    bool mediumScatterInPhotons() const { return maps_.global; }
    // Volume photons replace the sampled in-scattering of a participating medium.
    bool volumeFromPhotons() const { return maps_.volume; }

    // pmapamb.c: what the ambient term at a hit reads. A final-gather sample's hit (or any
    // hit with -ab -1) reads the global map, which holds caustic light too; hits of other
    // rays add the caustic map and gather the rest. Without a global map the caustic map
    // fills in at the samples' hits as well (ambPmapCaustic), or that light would be lost.
    // A contribution map plays both parts, its caustic photons the caustic map's.
    struct AmbientReads {
        bool contribGather = false;   // the contribution map's estimate is the whole term
        bool contribCaustic = false;  // add the contribution map's caustic photons
        bool global = false;          // the global map's estimate is the whole term
        bool caustic = false;         // add the caustic map's estimate
    };
    AmbientReads ambientReads(const PathDepth& p) const {
        return active() ? activeReads(p) : AmbientReads{};
    }

private:
    AmbientReads activeReads(const PathDepth& p) const;
    bool gatherHit(const PathDepth& p) const { return p.ambientLevel > 0 || bounces_ < 0; }
    PhotonMapKinds maps_;
    bool active_ = false;
    int bounces_ = 0;
};

}  // namespace rp::render
