/* darc's RenderMan Interface C binding (RI Spec 3.2, Appendix C naming).
 *
 * RiBegin(RI_NULL) (or "") renders in this process: each frame is rendered at its RiWorldEnd and
 * written to its RiDisplay file, exactly as the darc command renders the same requests given as
 * RIB (its default settings: the distance hider, every core). RiBegin("darc ARGS") renders with
 * the darc command's options ARGS (split at blanks, e.g. "darc --hider stochastic
 * --pixel-samples 4 --threads 2"; no RIB file names). RiBegin("scene.rib") writes the requests as
 * RIB text instead (the file appears whole at RiEnd); RiBegin("-") writes RIB to standard output.
 *
 * Parameter lists are RI_NULL-terminated token/value pairs (or, in the ...V forms, n tokens and n
 * values). A token is typed by its inline declaration ("vertex point P"), by RiDeclare, or by the
 * standard declarations (P, N, Cs, width, constantwidth, st, ...). How many values a parameter
 * has follows from its storage class and the request (RI Spec 3.2 section 5): for example a
 * "vertex" parameter of RiCurves has one element per control point.
 *
 * Errors and warnings go to the error handler (RiErrorHandler: RiErrorPrint by default) with the
 * position "<ri call N>", N counting this context's calls from RiBegin. RiErrorAbort stops the
 * context at the first error: later requests are ignored and no frame is written.
 *
 * Not supported (the request is accepted and a warning given, or it is not declared here): user
 * filter functions (RiPixelFilter takes the standard ones), RiProcDynamicLoad, RiTransformPoints,
 * RiMakeTexture and the other texture-making requests, RiBlobby, RiTrimCurve, solids, level-of-
 * detail requests (accepted without effect), RiArchiveRecord when rendering (it is written to RIB
 * files). Declarations made before RiBegin are not kept.
 */
#ifndef DARC_RI_H
#define DARC_RI_H

#ifdef __cplusplus
extern "C" {
#endif

typedef short RtBoolean;
typedef int RtInt;
typedef float RtFloat;
typedef const char* RtToken;
typedef const char* RtString;
typedef RtFloat RtColor[3];
typedef RtFloat RtPoint[3];
typedef RtFloat RtVector[3];
typedef RtFloat RtNormal[3];
typedef RtFloat RtHpoint[4];
typedef RtFloat RtMatrix[4][4];
typedef RtFloat RtBasis[4][4];
typedef RtFloat RtBound[6];
typedef void* RtPointer;
typedef void RtVoid;
typedef RtPointer RtObjectHandle;
typedef RtPointer RtLightHandle;
typedef RtPointer RtContextHandle;

typedef RtFloat (*RtFilterFunc)(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth);
typedef RtVoid (*RtErrorHandler)(RtInt code, RtInt severity, const char* message);
typedef RtVoid (*RtProcSubdivFunc)(RtPointer data, RtFloat detail);
typedef RtVoid (*RtProcFreeFunc)(RtPointer data);
typedef RtVoid (*RtArchiveCallback)(RtToken type, const char* format, ...);

#define RI_FALSE 0
#define RI_TRUE 1
#define RI_INFINITY 1.0e38f
#define RI_EPSILON 1.0e-10f
#define RI_NULL ((RtToken)0)

/* Error codes and severities (RI Spec 3.2 Appendix C). darc reports warnings as RIE_WARNING and
 * errors as RIE_ERROR, with the code RIE_CONSISTENCY (darc's messages say what is wrong). */
#define RIE_NOERROR 0
#define RIE_NOMEM 1
#define RIE_SYSTEM 2
#define RIE_NOFILE 3
#define RIE_BADFILE 4
#define RIE_VERSION 5
#define RIE_INCAPABLE 11
#define RIE_UNIMPLEMENT 12
#define RIE_LIMIT 13
#define RIE_BUG 14
#define RIE_NOTSTARTED 23
#define RIE_NESTING 24
#define RIE_NOTOPTIONS 25
#define RIE_NOTATTRIBS 26
#define RIE_NOTPRIMS 27
#define RIE_ILLSTATE 28
#define RIE_BADMOTION 29
#define RIE_BADSOLID 30
#define RIE_BADTOKEN 41
#define RIE_RANGE 42
#define RIE_CONSISTENCY 43
#define RIE_BADHANDLE 44
#define RIE_NOSHADER 45
#define RIE_MISSINGDATA 46
#define RIE_SYNTAX 47
#define RIE_MATH 61
#define RIE_INFO 0
#define RIE_WARNING 1
#define RIE_ERROR 2
#define RIE_SEVERE 3

/* Standard tokens. */
extern RtToken RI_FRAMEBUFFER, RI_FILE;
extern RtToken RI_RGB, RI_RGBA, RI_RGBZ, RI_RGBAZ, RI_A, RI_Z, RI_AZ;
extern RtToken RI_PERSPECTIVE, RI_ORTHOGRAPHIC;
extern RtToken RI_HIDDEN, RI_PAINT;
extern RtToken RI_CONSTANT, RI_SMOOTH;
extern RtToken RI_FLATNESS, RI_FOV;
extern RtToken RI_AMBIENTLIGHT, RI_POINTLIGHT, RI_DISTANTLIGHT, RI_SPOTLIGHT;
extern RtToken RI_INTENSITY, RI_LIGHTCOLOR, RI_FROM, RI_TO, RI_CONEANGLE, RI_CONEDELTAANGLE, RI_BEAMDISTRIBUTION;
extern RtToken RI_MATTE, RI_METAL, RI_SHINYMETAL, RI_PLASTIC, RI_PAINTEDPLASTIC;
extern RtToken RI_KA, RI_KD, RI_KS, RI_ROUGHNESS, RI_KR, RI_TEXTURENAME, RI_SPECULARCOLOR;
extern RtToken RI_P, RI_PZ, RI_PW, RI_N, RI_NP, RI_CS, RI_OS, RI_S, RI_T, RI_ST;
extern RtToken RI_WIDTH, RI_CONSTANTWIDTH;
extern RtToken RI_BILINEAR, RI_BICUBIC, RI_LINEAR, RI_CUBIC;
extern RtToken RI_PRIMITIVE, RI_INTERSECTION, RI_UNION, RI_DIFFERENCE;
extern RtToken RI_PERIODIC, RI_NONPERIODIC, RI_CLAMP, RI_BLACK;
extern RtToken RI_IGNORE, RI_PRINT, RI_ABORT;
extern RtToken RI_INSIDE, RI_OUTSIDE, RI_LH, RI_RH;
extern RtToken RI_CATMULLCLARK, RI_LOOP;
extern RtToken RI_COMMENT, RI_STRUCTURE, RI_VERBATIM;

/* Standard bases and their steps. */
extern RtBasis RiBezierBasis, RiBSplineBasis, RiCatmullRomBasis, RiHermiteBasis, RiPowerBasis;
#define RI_BEZIERSTEP 3
#define RI_BSPLINESTEP 1
#define RI_CATMULLROMSTEP 1
#define RI_HERMITESTEP 2
#define RI_POWERSTEP 4

/* Contexts. */
RtVoid RiBegin(RtToken name);
RtVoid RiEnd(void);
RtContextHandle RiGetContext(void);
RtVoid RiContext(RtContextHandle handle);
RtToken RiDeclare(const char* name, const char* declaration);
RtVoid RiErrorHandler(RtErrorHandler handler);
RtVoid RiErrorIgnore(RtInt code, RtInt severity, const char* message);
RtVoid RiErrorPrint(RtInt code, RtInt severity, const char* message);
RtVoid RiErrorAbort(RtInt code, RtInt severity, const char* message);

/* Blocks. */
RtVoid RiFrameBegin(RtInt frame);
RtVoid RiFrameEnd(void);
RtVoid RiWorldBegin(void);
RtVoid RiWorldEnd(void);
RtVoid RiAttributeBegin(void);
RtVoid RiAttributeEnd(void);
RtVoid RiTransformBegin(void);
RtVoid RiTransformEnd(void);
RtVoid RiMotionBegin(RtInt n, ...);
RtVoid RiMotionBeginV(RtInt n, RtFloat times[]);
RtVoid RiMotionEnd(void);
RtVoid RiResourceBegin(void);
RtVoid RiResourceEnd(void);

/* Options. */
RtVoid RiFormat(RtInt xres, RtInt yres, RtFloat pixel_aspect);
RtVoid RiFrameAspectRatio(RtFloat ratio);
RtVoid RiScreenWindow(RtFloat left, RtFloat right, RtFloat bottom, RtFloat top);
RtVoid RiCropWindow(RtFloat xmin, RtFloat xmax, RtFloat ymin, RtFloat ymax);
RtVoid RiProjection(RtToken name, ...);
RtVoid RiProjectionV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiClipping(RtFloat near_plane, RtFloat far_plane);
RtVoid RiDepthOfField(RtFloat fstop, RtFloat focal_length, RtFloat focal_distance);
RtVoid RiShutter(RtFloat open, RtFloat close);
RtVoid RiPixelVariance(RtFloat variation);
RtVoid RiColorSamples(RtInt n, RtFloat nRGB[], RtFloat RGBn[]); /* accepted without effect: RGB only */
RtVoid RiPixelSamples(RtFloat xsamples, RtFloat ysamples);
RtVoid RiPixelFilter(RtFilterFunc filter, RtFloat xwidth, RtFloat ywidth);
RtVoid RiExposure(RtFloat gain, RtFloat gamma);
RtVoid RiImager(RtToken name, ...);
RtVoid RiImagerV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiQuantize(RtToken type, RtInt one, RtInt min, RtInt max, RtFloat dither);
RtVoid RiDisplay(const char* name, RtToken type, RtToken mode, ...);
RtVoid RiDisplayV(const char* name, RtToken type, RtToken mode, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiCamera(RtToken name, ...);
RtVoid RiCameraV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiHider(RtToken type, ...);
RtVoid RiHiderV(RtToken type, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiOption(RtToken name, ...);
RtVoid RiOptionV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiIntegrator(RtToken name, RtToken handle, ...);
RtVoid RiIntegratorV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]);

/* The standard pixel filters (for RiPixelFilter; darc filters with its own implementations). */
RtFloat RiBoxFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth);
RtFloat RiTriangleFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth);
RtFloat RiCatmullRomFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth);
RtFloat RiGaussianFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth);
RtFloat RiSincFilter(RtFloat x, RtFloat y, RtFloat xwidth, RtFloat ywidth);

/* Attributes. */
RtVoid RiAttribute(RtToken name, ...);
RtVoid RiAttributeV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiColor(RtColor color);
RtVoid RiOpacity(RtColor opacity);
RtVoid RiSurface(RtToken name, ...);
RtVoid RiSurfaceV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiDisplacement(RtToken name, ...);
RtVoid RiDisplacementV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiAtmosphere(RtToken name, ...);
RtVoid RiAtmosphereV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiInterior(RtToken name, ...);
RtVoid RiInteriorV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiExterior(RtToken name, ...);
RtVoid RiExteriorV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtLightHandle RiLightSource(RtToken name, ...);
RtLightHandle RiLightSourceV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtLightHandle RiAreaLightSource(RtToken name, ...);
RtLightHandle RiAreaLightSourceV(RtToken name, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiIlluminate(RtLightHandle light, RtBoolean on);
RtVoid RiSides(RtInt sides);
RtVoid RiOrientation(RtToken orientation);
RtVoid RiReverseOrientation(void);
RtVoid RiBasis(RtBasis ubasis, RtInt ustep, RtBasis vbasis, RtInt vstep);
RtVoid RiMatte(RtBoolean onoff);
RtVoid RiShadingRate(RtFloat size);
RtVoid RiShadingInterpolation(RtToken type);
RtVoid RiGeometricApproximation(RtToken type, RtFloat value);
RtVoid RiDetail(RtBound bound);
RtVoid RiDetailRange(RtFloat minvisible, RtFloat lowertransition, RtFloat uppertransition, RtFloat maxvisible);
RtVoid RiRelativeDetail(RtFloat relativedetail);
RtVoid RiBound(RtBound bound); /* accepted without effect, as in RIB */
RtVoid RiTextureCoordinates(RtFloat s1, RtFloat t1, RtFloat s2, RtFloat t2, RtFloat s3, RtFloat t3, RtFloat s4,
                            RtFloat t4); /* accepted without effect, as in RIB */

/* RenderMan 21+ (RIS) shading: plugin name and handle. */
RtVoid RiBxdf(RtToken name, RtToken handle, ...);
RtVoid RiBxdfV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiPattern(RtToken name, RtToken handle, ...);
RtVoid RiPatternV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiLight(RtToken name, RtToken handle, ...);
RtVoid RiLightV(RtToken name, RtToken handle, RtInt n, RtToken tokens[], RtPointer values[]);

/* Transforms (matrices as RIB writes them: m[row][column], points as row vectors). */
RtVoid RiIdentity(void);
RtVoid RiTransform(RtMatrix transform);
RtVoid RiConcatTransform(RtMatrix transform);
RtVoid RiPerspective(RtFloat fov);
RtVoid RiTranslate(RtFloat dx, RtFloat dy, RtFloat dz);
RtVoid RiRotate(RtFloat angle, RtFloat dx, RtFloat dy, RtFloat dz);
RtVoid RiScale(RtFloat sx, RtFloat sy, RtFloat sz);
RtVoid RiSkew(RtFloat angle, RtFloat dx1, RtFloat dy1, RtFloat dz1, RtFloat dx2, RtFloat dy2, RtFloat dz2);
RtVoid RiCoordinateSystem(RtToken space);
RtVoid RiScopedCoordinateSystem(RtToken space);
RtVoid RiCoordSysTransform(RtToken space);

/* Instancing. */
RtObjectHandle RiObjectBegin(void);
RtVoid RiObjectEnd(void);
RtVoid RiObjectInstance(RtObjectHandle handle);

/* Geometry. */
RtVoid RiPolygon(RtInt nvertices, ...);
RtVoid RiPolygonV(RtInt nvertices, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiGeneralPolygon(RtInt nloops, RtInt nverts[], ...);
RtVoid RiGeneralPolygonV(RtInt nloops, RtInt nverts[], RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiPointsPolygons(RtInt npolys, RtInt nverts[], RtInt verts[], ...);
RtVoid RiPointsPolygonsV(RtInt npolys, RtInt nverts[], RtInt verts[], RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiPointsGeneralPolygons(RtInt npolys, RtInt nloops[], RtInt nverts[], RtInt verts[], ...);
RtVoid RiPointsGeneralPolygonsV(RtInt npolys, RtInt nloops[], RtInt nverts[], RtInt verts[], RtInt n,
                                RtToken tokens[], RtPointer values[]);
RtVoid RiPatch(RtToken type, ...);
RtVoid RiPatchV(RtToken type, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiPatchMesh(RtToken type, RtInt nu, RtToken uwrap, RtInt nv, RtToken vwrap, ...);
RtVoid RiPatchMeshV(RtToken type, RtInt nu, RtToken uwrap, RtInt nv, RtToken vwrap, RtInt n, RtToken tokens[],
                    RtPointer values[]);
RtVoid RiNuPatch(RtInt nu, RtInt uorder, RtFloat uknot[], RtFloat umin, RtFloat umax, RtInt nv, RtInt vorder,
                 RtFloat vknot[], RtFloat vmin, RtFloat vmax, ...);
RtVoid RiNuPatchV(RtInt nu, RtInt uorder, RtFloat uknot[], RtFloat umin, RtFloat umax, RtInt nv, RtInt vorder,
                  RtFloat vknot[], RtFloat vmin, RtFloat vmax, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiSubdivisionMesh(RtToken scheme, RtInt nfaces, RtInt nvertices[], RtInt vertices[], RtInt ntags,
                         RtToken tags[], RtInt nargs[], RtInt intargs[], RtFloat floatargs[], ...);
RtVoid RiSubdivisionMeshV(RtToken scheme, RtInt nfaces, RtInt nvertices[], RtInt vertices[], RtInt ntags,
                          RtToken tags[], RtInt nargs[], RtInt intargs[], RtFloat floatargs[], RtInt n,
                          RtToken tokens[], RtPointer values[]);
RtVoid RiSphere(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, ...);
RtVoid RiSphereV(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, RtInt n, RtToken tokens[],
                 RtPointer values[]);
RtVoid RiCone(RtFloat height, RtFloat radius, RtFloat thetamax, ...);
RtVoid RiConeV(RtFloat height, RtFloat radius, RtFloat thetamax, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiCylinder(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, ...);
RtVoid RiCylinderV(RtFloat radius, RtFloat zmin, RtFloat zmax, RtFloat thetamax, RtInt n, RtToken tokens[],
                   RtPointer values[]);
RtVoid RiHyperboloid(RtPoint point1, RtPoint point2, RtFloat thetamax, ...);
RtVoid RiHyperboloidV(RtPoint point1, RtPoint point2, RtFloat thetamax, RtInt n, RtToken tokens[],
                      RtPointer values[]);
RtVoid RiParaboloid(RtFloat rmax, RtFloat zmin, RtFloat zmax, RtFloat thetamax, ...);
RtVoid RiParaboloidV(RtFloat rmax, RtFloat zmin, RtFloat zmax, RtFloat thetamax, RtInt n, RtToken tokens[],
                     RtPointer values[]);
RtVoid RiDisk(RtFloat height, RtFloat radius, RtFloat thetamax, ...);
RtVoid RiDiskV(RtFloat height, RtFloat radius, RtFloat thetamax, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiTorus(RtFloat majorradius, RtFloat minorradius, RtFloat phimin, RtFloat phimax, RtFloat thetamax, ...);
RtVoid RiTorusV(RtFloat majorradius, RtFloat minorradius, RtFloat phimin, RtFloat phimax, RtFloat thetamax,
                RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiPoints(RtInt npoints, ...);
RtVoid RiPointsV(RtInt npoints, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiCurves(RtToken type, RtInt ncurves, RtInt nvertices[], RtToken wrap, ...);
RtVoid RiCurvesV(RtToken type, RtInt ncurves, RtInt nvertices[], RtToken wrap, RtInt n, RtToken tokens[],
                 RtPointer values[]);

/* Procedurals: expanded when they are given (after the frame is asked whether their bound can
 * reach the image), inside an attribute block. RiProcDelayedReadArchive's data is
 * { "file.rib" }, RiProcRunProgram's { "program", "its argument" }, as RtString arrays; a user
 * subdivide function is called with the bound's area in pixels (RI_INFINITY when unknown) and
 * makes RI calls itself; the free function, when given, is called once after it. */
RtVoid RiProcedural(RtPointer data, RtBound bound, RtProcSubdivFunc subdivide, RtProcFreeFunc free_data);
RtVoid RiProcDelayedReadArchive(RtPointer data, RtFloat detail);
RtVoid RiProcRunProgram(RtPointer data, RtFloat detail);
RtVoid RiProcDynamicLoad(RtPointer data, RtFloat detail);
RtVoid RiProcFree(RtPointer data);

/* Archives. RiReadArchive reads a RIB file (or an inline archive, or a "cache.zip!member.rib")
 * into the request stream; the callback is not called (darc reads no RIB comments). */
RtVoid RiReadArchive(RtToken name, RtArchiveCallback callback, ...);
RtVoid RiReadArchiveV(RtToken name, RtArchiveCallback callback, RtInt n, RtToken tokens[], RtPointer values[]);
RtVoid RiArchiveRecord(RtToken type, const char* format, ...);

#ifdef __cplusplus
}
#endif

#endif /* DARC_RI_H */
