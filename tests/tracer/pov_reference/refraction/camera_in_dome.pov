// glass_interiors.pov seen from inside a hollow dome. POV-Ray starts a
// camera ray in every interior that holds the eye (InitRayContainerState),
// and its ComputeRelativeIOR then gives a ray leaving glass into the dome
// a relative ior of 1: no Fresnel reflection inside the glass, where
// without the dome there is.
#include "glass_interiors.pov"
sphere { 0, 40 hollow pigment { rgbt <1, 0.95, 0.9, 0.4> } finish { ambient 0.3 diffuse 0 } }
