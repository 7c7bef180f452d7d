namespace MagnusBall.Integration
{
    /// <summary>
    /// Heun's method for a ball rolling on a surface, the one place its combination is written (the flight core's roll,
    /// Flight/FlightStepper.Rolling.cs, calls it): an Euler predictor, then the trapezoid of the accelerations for the
    /// velocity and of the velocities for the position. Second order, and exact for a constant acceleration, so exact on
    /// level ground in still air. Split in two because the roll checks for a stop between the predictor and the corrector.
    /// </summary>
    internal static class RollingHeun
    {
        /// <summary>The predictor: p~ = p0 + h v0, v~ = v0 + h a0.</summary>
        internal static void Predict(in Vector3d p0, in Vector3d v0, in Vector3d a0, double h, out Vector3d position, out Vector3d velocity)
        {
            position = p0 + v0 * h;
            velocity = v0 + a0 * h;
        }

        /// <summary>The corrector: a = (a0 + a1) / 2, v1 = v0 + h a, p1 = p0 + h (v0 + v1) / 2, with a1 the acceleration at the predicted state.</summary>
        internal static void Correct(
            in Vector3d p0, in Vector3d v0, in Vector3d a0, in Vector3d a1, double h,
            out Vector3d averageAcceleration, out Vector3d position, out Vector3d velocity)
        {
            averageAcceleration = (a0 + a1) * 0.5;
            velocity = v0 + averageAcceleration * h;
            position = p0 + (v0 + velocity) * (0.5 * h);
        }
    }
}
