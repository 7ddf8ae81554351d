/** Barrel of src/physics: the pure kernels users may want (motion evaluation, time of impact, response). */
export { type MotionLaw, motionLaw, positionAt, velocityAt } from "./motion.js";
export { firstDownCrossingQuadratic } from "./quadraticCrossing.js";
export { firstDownCrossingQuartic } from "./quarticCrossing.js";
export { discDiscResponse, impulseMagnitude, impulseShare, reflectResponse } from "./response.js";
export { discDiscTime } from "./timeOfImpact.js";
