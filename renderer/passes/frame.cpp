#include "renderer/passes/frame.h"

#include <bit>
#include <string>

#include "renderer/common/error.h"

namespace ds::passes {

FrameOptions FrameOptions::from(const Settings& s) {
    FrameOptions o;
    o.prepass = s.get_bool("prepass");
    o.depth_equal = s.get("depth_compare") == "equal";
    o.masked_split = s.get_bool("masked_split");
    o.prepass_sort = s.get_bool("prepass_sort");
    if (s.get("alpha_cutoff") != "material") o.alpha_cutoff = s.get_float("alpha_cutoff");
    o.shadows = s.get_bool("shadows");
    // GTAO and contact shadows read the prepass depth (and normals): no prepass, no effect.
    o.gtao = s.get_bool("gtao") && o.prepass;
    o.contact_shadows = s.get_bool("contact_shadows") && o.prepass;
    o.sky = s.get_bool("sky");
    o.invariant = s.get_bool("invariant");
    o.reverse_z = s.get_bool("reverse_z");
    // equal_check reads forward's per-pixel counts and names the surfaces that won.
    o.equal_check =
        s.get_bool("equal_check") && o.prepass && o.depth_equal && s.get_int("msaa") == 1;
    o.count_fragments = s.get_bool("count_fragments") || o.equal_check;
    // The registry allows 1..8; VkSampleCountFlagBits are the powers of two themselves.
    const int msaa = s.get_int("msaa");
    if (!std::has_single_bit(unsigned(msaa)))
        throw Error("setting msaa: " + std::to_string(msaa) +
                    " is not a power of two (1, 2, 4, 8)");
    o.samples = VkSampleCountFlagBits(msaa);
    o.count_discards = s.get_bool("count_discards");
    // Both act on multisampled targets only; at 1x they would change nothing but the key.
    o.sample_shading = s.get_bool("sample_shading") && o.msaa();
    o.alpha_to_coverage = s.get_bool("alpha_to_coverage") && o.msaa();
    // Both diagnostics compare against the prepass's depth and winner; the detector compares
    // at pixel centres, which a multisampled depth (stored at sample positions) is not.
    o.zfight = s.get_bool("zfight") && o.prepass && !o.msaa();
    o.zfight_steps = uint32_t(s.get_int("zfight_steps"));
    o.surface_id = (s.get_bool("surface_id") || o.zfight || o.equal_check) && o.prepass;
    return o;
}

}  // namespace ds::passes
