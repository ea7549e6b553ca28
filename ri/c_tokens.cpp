// The standard tokens and bases of ri.h.
#include "ri/ri.h"

extern "C" {

RtToken RI_FRAMEBUFFER = "framebuffer";
RtToken RI_FILE = "file";
RtToken RI_RGB = "rgb";
RtToken RI_RGBA = "rgba";
RtToken RI_RGBZ = "rgbz";
RtToken RI_RGBAZ = "rgbaz";
RtToken RI_A = "a";
RtToken RI_Z = "z";
RtToken RI_AZ = "az";
RtToken RI_PERSPECTIVE = "perspective";
RtToken RI_ORTHOGRAPHIC = "orthographic";
RtToken RI_HIDDEN = "hidden";
RtToken RI_PAINT = "paint";
RtToken RI_CONSTANT = "constant";
RtToken RI_SMOOTH = "smooth";
RtToken RI_FLATNESS = "flatness";
RtToken RI_FOV = "fov";
RtToken RI_AMBIENTLIGHT = "ambientlight";
RtToken RI_POINTLIGHT = "pointlight";
RtToken RI_DISTANTLIGHT = "distantlight";
RtToken RI_SPOTLIGHT = "spotlight";
RtToken RI_INTENSITY = "intensity";
RtToken RI_LIGHTCOLOR = "lightcolor";
RtToken RI_FROM = "from";
RtToken RI_TO = "to";
RtToken RI_CONEANGLE = "coneangle";
RtToken RI_CONEDELTAANGLE = "conedeltaangle";
RtToken RI_BEAMDISTRIBUTION = "beamdistribution";
RtToken RI_MATTE = "matte";
RtToken RI_METAL = "metal";
RtToken RI_SHINYMETAL = "shinymetal";
RtToken RI_PLASTIC = "plastic";
RtToken RI_PAINTEDPLASTIC = "paintedplastic";
RtToken RI_KA = "Ka";
RtToken RI_KD = "Kd";
RtToken RI_KS = "Ks";
RtToken RI_ROUGHNESS = "roughness";
RtToken RI_KR = "Kr";
RtToken RI_TEXTURENAME = "texturename";
RtToken RI_SPECULARCOLOR = "specularcolor";
RtToken RI_P = "P";
RtToken RI_PZ = "Pz";
RtToken RI_PW = "Pw";
RtToken RI_N = "N";
RtToken RI_NP = "Np";
RtToken RI_CS = "Cs";
RtToken RI_OS = "Os";
RtToken RI_S = "s";
RtToken RI_T = "t";
RtToken RI_ST = "st";
RtToken RI_WIDTH = "width";
RtToken RI_CONSTANTWIDTH = "constantwidth";
RtToken RI_BILINEAR = "bilinear";
RtToken RI_BICUBIC = "bicubic";
RtToken RI_LINEAR = "linear";
RtToken RI_CUBIC = "cubic";
RtToken RI_PRIMITIVE = "primitive";
RtToken RI_INTERSECTION = "intersection";
RtToken RI_UNION = "union";
RtToken RI_DIFFERENCE = "difference";
RtToken RI_PERIODIC = "periodic";
RtToken RI_NONPERIODIC = "nonperiodic";
RtToken RI_CLAMP = "clamp";
RtToken RI_BLACK = "black";
RtToken RI_IGNORE = "ignore";
RtToken RI_PRINT = "print";
RtToken RI_ABORT = "abort";
RtToken RI_INSIDE = "inside";
RtToken RI_OUTSIDE = "outside";
RtToken RI_LH = "lh";
RtToken RI_RH = "rh";
RtToken RI_CATMULLCLARK = "catmull-clark";
RtToken RI_LOOP = "loop";
RtToken RI_COMMENT = "comment";
RtToken RI_STRUCTURE = "structure";
RtToken RI_VERBATIM = "verbatim";

// The standard bases (RI Spec 3.2 section 4.2.3), rows multiplying [t^3 t^2 t 1] as RiBasis takes them.
RtBasis RiBezierBasis = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}};
RtBasis RiBSplineBasis = {{-1.0f / 6, 3.0f / 6, -3.0f / 6, 1.0f / 6},
                          {3.0f / 6, -6.0f / 6, 3.0f / 6, 0},
                          {-3.0f / 6, 0, 3.0f / 6, 0},
                          {1.0f / 6, 4.0f / 6, 1.0f / 6, 0}};
RtBasis RiCatmullRomBasis = {{-0.5f, 1.5f, -1.5f, 0.5f}, {1, -2.5f, 2, -0.5f}, {-0.5f, 0, 0.5f, 0}, {0, 1, 0, 0}};
RtBasis RiHermiteBasis = {{2, 1, -2, 1}, {-3, -2, 3, -1}, {0, 1, 0, 0}, {1, 0, 0, 0}};
RtBasis RiPowerBasis = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

}  // extern "C"
