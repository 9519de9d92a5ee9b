#pragma once
// Loading an environment map from a file, whatever its layout: a lat-long map (OpenEXR or
// Radiance .hdr), an OpenEXR cube map (the standard `envmap` attribute = cube, a W x 6W strip),
// or a light probe photographed as a mirror ball or stored as an angular map. Everything is
// converted to the lat-long EnvironmentMap the programs share (docs/conventions.md).

#include <filesystem>
#include <string>

#include "core/enum_names.h"
#include "core/environment_map.h"

namespace iblkit {

enum class ProbeFormat { LatLong, MirrorBall, Angular };

inline constexpr EnumName<ProbeFormat> kProbeFormatNames[] = {{ProbeFormat::LatLong, "latlong"},
                                                              {ProbeFormat::MirrorBall, "mirrorball"},
                                                              {ProbeFormat::Angular, "angular"}};

// A name of the table above; otherwise throws Error("<what>: unknown environment format 'x'
// (expected one of latlong, mirrorball, angular)"), `what` being the option or file that gave it.
ProbeFormat parseProbeFormat(const std::string& name, const std::string& what = "--env-format");

// Reads `file` as a lat-long map (an OpenEXR file whose envmap attribute says cube is converted
// from its cube faces), or converts a square mirror-ball / angular-map probe. Converted maps are
// `latLongWidth` x latLongWidth/2 (0: twice the source's height, or 4x a cube face's size).
// Bad input throws Error("<file>: <problem>"). NaN and Inf values become 0; negative ones (DWAB
// ringing) are repaired keeping the map's integral (repairNegativeRadiance, after any conversion,
// which sees them as stored); one warning naming the file says what moved.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& file,
                                  ProbeFormat format = ProbeFormat::LatLong, int latLongWidth = 0);

}  // namespace iblkit
