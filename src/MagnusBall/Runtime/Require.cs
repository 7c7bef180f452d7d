using System;
using System.Globalization;

namespace MagnusBall
{
    /// <summary>
    /// Argument checks shared by every public entry point. Each throws before anything is changed and
    /// names the parameter, the value it got and the range it allows.
    /// </summary>
    internal static class Require
    {
        internal static double Finite(double value, string name)
        {
            if (!double.IsFinite(value))
            {
                throw new ArgumentOutOfRangeException(name, value, $"{name} must be a finite number; got {Format(value)}.");
            }

            return value;
        }

        internal static double Positive(double value, string name)
        {
            if (!double.IsFinite(value) || value <= 0)
            {
                throw new ArgumentOutOfRangeException(name, value, $"{name} must be finite and > 0; got {Format(value)}.");
            }

            return value;
        }

        internal static double NonNegative(double value, string name)
        {
            if (!double.IsFinite(value) || value < 0)
            {
                throw new ArgumentOutOfRangeException(name, value, $"{name} must be finite and >= 0; got {Format(value)}.");
            }

            return value;
        }

        internal static double InRange(double value, double min, double max, string name)
        {
            if (!double.IsFinite(value) || value < min || value > max)
            {
                throw new ArgumentOutOfRangeException(
                    name, value, $"{name} must be in [{Format(min)}, {Format(max)}]; got {Format(value)}.");
            }

            return value;
        }

        internal static double Step(double step, string name = "step")
        {
            if (!double.IsFinite(step) || step <= 0)
            {
                throw new ArgumentOutOfRangeException(name, step, $"{name} must be a finite time step > 0 s; got {Format(step)}.");
            }

            return step;
        }

        internal static Vector3d Finite(in Vector3d value, string name)
        {
            if (!value.IsFinite)
            {
                throw new ArgumentException($"{name} must have finite components; got {value}.", name);
            }

            return value;
        }

        internal static Vector3d NonZero(in Vector3d value, string name)
        {
            Finite(value, name);
            if (value.LengthSquared == 0)
            {
                throw new ArgumentException($"{name} must be a finite non-zero vector; got {value}.", name);
            }

            return value;
        }

        /// <summary>The one finite-state check: position, velocity, angular velocity and time all finite.</summary>
        internal static void FiniteState(in FlightState state, string name)
        {
            if (!state.IsFinite)
            {
                throw new ArgumentException($"{name} must have finite position, velocity, angular velocity and time; got {state}.", name);
            }
        }

        internal static T NotNull<T>(T? value, string name)
            where T : class
        {
            if (value is null)
            {
                throw new ArgumentNullException(name, $"{name} must not be null.");
            }

            return value;
        }

        internal static string Format(double value) => value.ToString("R", CultureInfo.InvariantCulture);
    }
}
