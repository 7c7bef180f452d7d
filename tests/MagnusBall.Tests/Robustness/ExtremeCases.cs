using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Queries;

namespace MagnusBall.Tests.Robustness
{
    /// <summary>
    /// The balls and the flight loop of the extremes matrix, defined here so the tests do not depend on presets.
    /// Same definitions as benchmarks/MagnusBall.Benchmarks/Scenarios.cs (the full matrix).
    /// </summary>
    internal static class ExtremeCases
    {
        public static readonly Vector3d Up = Vector3d.UnitZ;

        /// <summary>(name, model): table tennis 2.7 g/20 mm, tennis, soccer, golf, baseball, a 120 g/250 mm beach ball.</summary>
        public static readonly (string Name, FlightModel Model)[] Balls =
        {
            ("table tennis", Model(new Ball(0.0027, 0.020, Ball.ThinShellInertiaFactor), new ConstantDrag(0.5), 2)),
            ("tennis", Model(Ball.Tennis, StepanekDrag.Instance, 20)),
            ("soccer", Model(new Ball(0.43, 0.11, Ball.ThinShellInertiaFactor), new ConstantDrag(0.25), 10)),
            ("golf", Model(new Ball(0.0459, 0.02135, 0.4), new ConstantDrag(0.25), 25)),
            ("baseball", Model(new Ball(0.145, 0.0364, 0.4), new ConstantDrag(0.35), 5)),
            ("beach ball", Model(new Ball(0.12, 0.25, Ball.ThinShellInertiaFactor), new ConstantDrag(0.47), 2)),
        };

        private static FlightModel Model(Ball ball, IDragModel drag, double spinDecayTime) =>
            new FlightModel(ball, Air.SeaLevel, Gravity.ZUp, drag, StepanekLift.Instance, new ExponentialSpinDecay(spinDecayTime));

        /// <summary>From 1 m at 10 deg along +x; spin along, across or oblique (45 deg) to the velocity.</summary>
        public static FlightState Launch(double speed, double spinRate, string orientation)
        {
            double e = 10 * Math.PI / 180;
            var direction = new Vector3d(Math.Cos(e), 0, Math.Sin(e));
            Vector3d across = Vector3d.Cross(direction, Up).NormalizedOrZero();
            Vector3d axis = orientation == "along" ? direction : orientation == "across" ? across : (direction + across).NormalizedOrZero();
            return new FlightState(new Vector3d(0, 0, 1), direction * speed, axis * spinRate);
        }

        public struct Outcome
        {
            public bool Finite;
            public bool Landed;
            public bool Diverged;
            public double MaxEnergyRise;
            public Vector3d Landing;
        }

        /// <summary>Flies to the landing with StableStepping over <paramref name="integrator"/>, checking every step.</summary>
        public static Outcome Fly(FlightModel model, IIntegrator integrator, FlightState state, double step, double maxTime = 60)
        {
            var outcome = new Outcome { Finite = true };
            StateDerivative derivative = model.Derivative(state);
            double s0 = state.Velocity.Length, g = model.Gravity.Length, m = model.Ball.Mass;
            while (state.Time < maxTime)
            {
                FlightState next = StableStepping.Step(integrator, model, state, derivative, step, out StateDerivative end, out _);
                if (!next.IsFinite || !end.Acceleration.IsFinite)
                {
                    outcome.Finite = false;
                    return outcome;
                }

                double scale = m * (0.5 * Math.Max(state.Velocity.LengthSquared, next.Velocity.LengthSquared) +
                                    g * Math.Max(state.Position.Length, next.Position.Length) + g);
                outcome.MaxEnergyRise = Math.Max(outcome.MaxEnergyRise, (model.MechanicalEnergy(next) - model.MechanicalEnergy(state)) / scale);
                outcome.Diverged |= next.Velocity.Length > s0 + g * next.Time + 1e-9;
                if (TryLand(state, derivative, next, end, out outcome.Landing))
                {
                    outcome.Landed = true;
                    return outcome;
                }

                state = next;
                derivative = end;
            }

            return outcome;
        }

        /// <summary>The reference landing: DP54 at rtol = atol = 1e-10, located on its own dense output.</summary>
        public static Vector3d ReferenceLanding(FlightModel model, FlightState state)
        {
            var method = new DormandPrince54(1e-10, 1e-10);
            StateDerivative derivative = model.Derivative(state);
            double step = method.InitialStep(model, state, derivative, 0.01);
            while (state.Time < 60)
            {
                bool accepted = method.TryStep(model, state, derivative, step, out DormandPrince54Step result);
                step = result.NextStep;
                if (!accepted)
                {
                    continue;
                }

                if (Vector3d.Dot(result.Start.Position, Up) >= 0 && Vector3d.Dot(result.End.Position, Up) < 0)
                {
                    double lo = 0, hi = 1;
                    for (int i = 0; i < 80 && hi - lo > 1e-16; i++)
                    {
                        double mid = 0.5 * (lo + hi);
                        if (Vector3d.Dot(result.InterpolateFraction(mid).Position, Up) >= 0)
                        {
                            lo = mid;
                        }
                        else
                        {
                            hi = mid;
                        }
                    }

                    return result.InterpolateFraction(0.5 * (lo + hi)).Position;
                }

                state = result.End;
                derivative = result.EndDerivative;
            }

            throw new InvalidOperationException("the reference flight did not land");
        }

        private static readonly Plane Ground = new Plane(default, Up);

        /// <summary>The first crossing of the ground inside a step, on the step's cubic Hermite (the queries API).</summary>
        public static bool TryLand(in FlightState a, in StateDerivative da, in FlightState b, in StateDerivative db, out Vector3d landing)
        {
            var segment = new HermiteSegment(a, da, b, db);
            if (segment.TryFindCrossing(Ground, CrossingDirection.AgainstNormal, out double time))
            {
                landing = segment.PositionAt(time);
                return true;
            }

            landing = default;
            return false;
        }
    }
}
