using System;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Tests.Integration
{
    /// <summary>The scales the conformance test measures a fast form's rounding against.</summary>
    internal static class Rounding
    {
        /// <summary>
        /// |g| + k s^2 (|C_D| + |C_L|) at the state, with the laws' own coefficients at the general formula's conditions:
        /// the largest terms of the acceleration, the scale a folded form's rounding is measured against.
        /// </summary>
        internal static double ForceScale(FlightModel model, in FlightState state)
        {
            double g = model.Gravity.Length;
            Vector3d relative = state.Velocity - model.Air.WindAt(state.Position, model.Up);
            double speed = relative.Length;
            if (!(model.Air.Density > 0 && speed > FlightModel.MinimumAerodynamicSpeed))
            {
                return g;
            }

            double transverse = Vector3d.Cross(state.AngularVelocity, relative / speed).Length;
            var conditions = new AeroConditions(speed, state.AngularVelocity.Length, transverse, model.Ball.Radius, model.Air.Density, model.Air.DynamicViscosity);
            double c = Math.Abs(model.Drag?.DragCoefficient(conditions) ?? 0) + Math.Abs(model.Lift?.LiftCoefficient(conditions) ?? 0);
            return g + model.AerodynamicFactor * speed * speed * c;
        }

        /// <summary>The gap to the next double up from |value| (infinity where it is not finite; Math.BitIncrement is not in .NET Framework, which the Mono run compiles against).</summary>
        internal static double Ulp(double value)
        {
            double x = Math.Abs(value);
            return !double.IsInfinity(x) && !double.IsNaN(x) ? BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(x) + 1) - x : double.PositiveInfinity;
        }

    }
}
