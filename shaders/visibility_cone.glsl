// The axis of the visibility cone (mesh.frag, mesh.vert): the baked bent normal, turned towards n as
// the AO nears 1. An unoccluded vertex sees its whole hemisphere, a 90-degree cone about n; its bent
// normal is n only on average, and with few bake rays a tilted one would cut off part of that
// hemisphere. A fully occluded vertex (no bent normal, zero length) keeps n.
vec3 visibilityConeAxis(vec3 bentNormal, vec3 n, float ao) {
  float length2 = dot(bentNormal, bentNormal);
  vec3 bent = length2 > 1e-8 ? bentNormal * inversesqrt(length2) : n;
  return normalize(mix(bent, n, ao));
}
