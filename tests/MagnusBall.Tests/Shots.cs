using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;

namespace MagnusBall.Tests
{
    /// <summary>Shared shots and a plain fixed-step flight loop for the core tests.</summary>
    internal static class Shots
    {
        /// <summary>Cross (2011) air: rho 1.21 kg/m^3.</summary>
        public static readonly Air CrossAir = new Air(1.21);

        /// <summary>The full Stepanek tennis model in a z-up frame.</summary>
        public static FlightModel StepanekTennis(Vector3d gravity) =>
            new FlightModel(Ball.Tennis, CrossAir, gravity, StepanekDrag.Instance, StepanekLift.Instance);

        /// <summary>A 30 m/s drive from 1 m at 8 degrees in a z-up frame (x downrange), with the given spin.</summary>
        public static FlightState ZUpDrive(Vector3d spin, double speed = 30, double elevationDegrees = 8)
        {
            double e = elevationDegrees * Math.PI / 180;
            return new FlightState(new Vector3d(0, 0, 1), new Vector3d(speed * Math.Cos(e), 0, speed * Math.Sin(e)), spin);
        }

        /// <summary>Steps <paramref name="count"/> fixed steps, reusing the end derivative as the next start.</summary>
        public static FlightState Fly(FlightModel model, IIntegrator integrator, FlightState state, double step, int count)
        {
            StateDerivative derivative = model.Derivative(state);
            for (int i = 0; i < count; i++)
            {
                state = integrator.Step(model, state, derivative, step);
                derivative = model.Derivative(state);
            }

            return state;
        }

        /// <summary>
        /// Flies until the height along <paramref name="up"/> falls below zero and returns the crossing point,
        /// interpolated linearly inside the last step (enough for sign and frame checks; the event queries
        /// give the exact crossing).
        /// </summary>
        public static Vector3d Landing(FlightModel model, IIntegrator integrator, FlightState state, Vector3d up, double step, double maxTime = 20)
        {
            StateDerivative derivative = model.Derivative(state);
            while (state.Time < maxTime)
            {
                FlightState next = integrator.Step(model, state, derivative, step);
                double h0 = Vector3d.Dot(state.Position, up);
                double h1 = Vector3d.Dot(next.Position, up);
                if (h0 >= 0 && h1 < 0)
                {
                    return Vector3d.Lerp(state.Position, next.Position, h0 / (h0 - h1));
                }

                state = next;
                derivative = model.Derivative(state);
            }

            throw new InvalidOperationException("the ball did not land within maxTime");
        }
    }
}
