#ifndef VIEW_LAYERS_GLSL
#define VIEW_LAYERS_GLSL
// A view of the capture (DeviceView): 4 layers of W*H vec4 texels, bound as the 4 descriptors of
// one array binding so that each layer is its own range and a view binds wherever one layer fits
// maxStorageBufferRange. The includer may set VIEW_BINDING (default 0). The array is indexed by
// constants only, so no descriptor-indexing feature is needed.
#ifndef VIEW_BINDING
#define VIEW_BINDING 0
#endif
layout(std430, binding = VIEW_BINDING) readonly buffer ViewLayer { vec4 texels[]; } view_layers[4];

vec4 view_position_valid(uint i) { return view_layers[0].texels[i]; }      // P, valid
vec4 view_normal_pdf(uint i) { return view_layers[1].texels[i]; }          // N, pdf
vec4 view_diffuse_roughness(uint i) { return view_layers[2].texels[i]; }   // diffuse albedo, roughness
vec4 view_specular(uint i) { return view_layers[3].texels[i]; }            // specular albedo, 0

#endif
