// The GLSL sources of shaders/, compiled in (cmake/KerfEmbedText.cmake).
#pragma once

namespace kerf::render::shaders {
extern const char* const kSurfaceVert;
extern const char* const kSurfaceFrag;
extern const char* const kLinesVert;
extern const char* const kLinesGeom;
extern const char* const kLinesFrag;
extern const char* const kMarkerVert;
extern const char* const kMarkerFrag;
extern const char* const kOverlayVert;
extern const char* const kOverlayFrag;
}  // namespace kerf::render::shaders
