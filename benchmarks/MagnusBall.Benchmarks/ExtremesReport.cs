using System;
using MagnusBall.Flight;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using MagnusBall.Integration;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// The extremes matrix (balls x speeds x spins x steps, every integrator raw and RK4 through StableStepping) and the
    /// blow-up steps of each integrator. Console modes "extremes" and "blowup"; they print markdown for docs/integrators.md.
    /// </summary>
    internal static class ExtremesReport
    {
        public static readonly double[] Speeds = { 0, 1e-3, 1, 30, 70, 100 };
        public static readonly double[] SpinRates = { 0, 50, 500, 1000 };
        public static readonly string[] Orientations = { "along", "across", "oblique" };
        public static readonly double[] Steps = { 1e-4, 1.0 / 240, 1.0 / 60, 1.0 / 30, 0.1, 0.25 };
        private const double MaxTime = 60;
        private const double LaunchElevationDegrees = 10;

        private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

        public static FlightState Launch(double speed, double spinRate, string orientation)
        {
            double e = LaunchElevationDegrees * Math.PI / 180;
            var direction = new Vector3d(Math.Cos(e), 0, Math.Sin(e));
            Vector3d across = Vector3d.Cross(direction, Scenarios.Up).NormalizedOrZero();
            Vector3d axis = orientation == "along" ? direction : orientation == "across" ? across : (direction + across).NormalizedOrZero();
            return new FlightState(new Vector3d(0, 0, 1), direction * speed, axis * spinRate);
        }

        /// <summary>The outcome of one flight.</summary>
        public struct Outcome
        {
            public bool Finite;
            public bool Landed;
            public bool Diverged; // speed above s0 + |g| t
            public double MaxEnergyRise; // largest per-step rise of mechanical energy over the energy scale
            public Vector3d Landing;
            public long Evaluations;
        }

        public static Outcome Fly(FlightModel model, IIntegrator integrator, bool stable, FlightState state, double step)
        {
            // Through the library's one flight core, with the ground as a stop event: a refused (diverging) step is a
            // non-finite outcome; each taken step is checked for energy rise and run-away speed.
            var outcome = new Outcome { Finite = true };
            var stepper = new FlightStepper(model, stable ? new StableIntegrator(integrator) : integrator, new FlightEventSet(Vector3d.Zero, LandingLocator.Ground));
            stepper.Reset(state);
            double s0 = state.Velocity.Length;
            double g = model.Gravity.Length;
            double m = model.Ball.Mass;
            while (stepper.State.Time < MaxTime)
            {
                FlightState before = stepper.State;
                StepOutcome taken = stepper.TryStep(step, FlightEventKinds.Landing);
                outcome.Evaluations = stepper.DerivativeEvaluations;
                if (taken == StepOutcome.Diverged || taken == StepOutcome.TimeCannotAdvance)
                {
                    outcome.Finite = false;
                    return outcome;
                }

                FlightState next = stepper.State;
                double e0 = model.MechanicalEnergy(before), e1 = model.MechanicalEnergy(next);
                double scale = m * (0.5 * Math.Max(before.Velocity.LengthSquared, next.Velocity.LengthSquared) +
                                    g * Math.Max(before.Position.Length, next.Position.Length) + g);
                outcome.MaxEnergyRise = Math.Max(outcome.MaxEnergyRise, (e1 - e0) / scale);
                if (next.Velocity.Length > s0 + g * next.Time + 1e-9)
                {
                    outcome.Diverged = true;
                }

                if (stepper.IsStopped)
                {
                    outcome.Landed = true;
                    outcome.Landing = stepper.StopEvent.Position;
                    return outcome;
                }
            }

            return outcome;
        }


        /// <summary>The full matrix, summarised per (method, step) and, for the default stepping, per (ball, step).</summary>
        public static string Matrix(bool quick)
        {
            var watch = Stopwatch.StartNew();
            var methods = new List<(string Name, IIntegrator Integrator, bool Stable)>();
            foreach (IIntegrator integrator in Scenarios.FixedStepIntegrators)
            {
                methods.Add((integrator.Name, integrator, false));
            }

            methods.Add(("stable-euler", ExplicitEuler.Instance, true));
            methods.Add(("stable-rk4 (default)", RungeKutta4.Instance, true));

            int cells = 0;
            var nonFinite = new Dictionary<(int, int), int>();
            var diverged = new Dictionary<(int, int), int>();
            var energyRise = new Dictionary<(int, int), int>();
            var notLanded = new Dictionary<(int, int), int>();
            var worstRise = new Dictionary<(int, int), double>();
            var worstError = new Dictionary<(int, int), double>(); // (ball, step) for the default stepping
            var worstErrorMethod = new Dictionary<(int, int), double>(); // (method, step), landed cells only
            var worstErrorCell = new Dictionary<(int, int), string>();
            long defaultEvaluations = 0;

            double[] steps = quick ? new[] { 1.0 / 240, 1.0 / 30, 0.25 } : Steps;
            for (int b = 0; b < Scenarios.Balls.Length; b++)
            {
                BallCase ball = Scenarios.Balls[b];
                FlightModel model = ball.Model(Scenarios.G);
                foreach (double speed in Speeds)
                {
                    foreach (double rate in SpinRates)
                    {
                        foreach (string orientation in rate == 0 ? new[] { "along" } : Orientations)
                        {
                            FlightState launch = Launch(speed, rate, orientation);
                            bool haveReference = Flight.TryLandReference(model, launch, MaxTime, 1e-10, out Vector3d reference, out _);
                            for (int si = 0; si < steps.Length; si++)
                            {
                                cells++;
                                for (int mi = 0; mi < methods.Count; mi++)
                                {
                                    Outcome o = Fly(model, methods[mi].Integrator, methods[mi].Stable, launch, steps[si]);
                                    var key = (mi, si);
                                    Bump(nonFinite, key, !o.Finite);
                                    Bump(diverged, key, o.Diverged);
                                    Bump(energyRise, key, o.MaxEnergyRise > 1e-12);
                                    Bump(notLanded, key, o.Finite && !o.Landed);
                                    worstRise[key] = Math.Max(worstRise.TryGetValue(key, out double r) ? r : 0, o.MaxEnergyRise);
                                    if (o.Landed && haveReference)
                                    {
                                        double error = Vector3d.Distance(o.Landing, reference);
                                        if (!worstErrorMethod.TryGetValue(key, out double w) || error > w)
                                        {
                                            worstErrorMethod[key] = error;
                                            worstErrorCell[key] = $"{ball.Name} {speed.ToString("G", Inv)} m/s {rate.ToString("G", Inv)} rad/s {orientation}";
                                        }

                                        if (methods[mi].Stable && methods[mi].Integrator == RungeKutta4.Instance)
                                        {
                                            worstError[(b, si)] = Math.Max(worstError.TryGetValue((b, si), out double e) ? e : 0, error);
                                        }
                                    }

                                    if (methods[mi].Stable && methods[mi].Integrator == RungeKutta4.Instance)
                                    {
                                        defaultEvaluations += o.Evaluations;
                                    }
                                }
                            }
                        }
                    }
                }
            }

            var sb = new StringBuilder();
            sb.AppendLine($"Matrix: {Scenarios.Balls.Length} balls x {Speeds.Length} speeds x 10 spins (0; 50, 500, 1000 rad/s along, across, oblique) x {steps.Length} steps = {cells} cells, each flown by {methods.Count} methods from 1 m at {LaunchElevationDegrees} deg until it lands (or {MaxTime} s). Reference: DP54 at 1e-10. Run time {watch.Elapsed.TotalSeconds:F0} s.");
            sb.AppendLine();
            sb.AppendLine("Per method and step, over the cells of that step: cells that went non-finite / whose speed grew beyond s0 + g t (diverged) / whose energy rose in some step by more than 1e-12 of its scale / that never landed; the largest energy rise in one step (relative); the worst landing error against the reference among the cells that landed.");
            sb.AppendLine();
            sb.Append("| method | step (s) | non-finite | diverged | energy rose | not landed | max rise | worst landing error (m) | worst cell |").AppendLine();
            sb.Append("|---|---|---|---|---|---|---|---|---|").AppendLine();
            int perStep = cells / steps.Length;
            for (int mi = 0; mi < methods.Count; mi++)
            {
                for (int si = 0; si < steps.Length; si++)
                {
                    var key = (mi, si);
                    sb.Append($"| {methods[mi].Name} | {StepName(steps[si])} | {Get(nonFinite, key)}/{perStep} | {Get(diverged, key)} | {Get(energyRise, key)} | {Get(notLanded, key)} | {worstRise[key].ToString("E1", Inv)} | ");
                    sb.Append(worstErrorMethod.TryGetValue(key, out double w) ? w.ToString("E2", Inv) : "-").Append(" | ");
                    sb.Append(worstErrorCell.TryGetValue(key, out string? cell) ? cell : "-").AppendLine(" |");
                }
            }

            sb.AppendLine();
            sb.AppendLine("Default stepping (RK4 through StableStepping, landing on the step's cubic Hermite): worst landing error (m) against the reference, per ball and step, over all speeds and spins of that ball.");
            sb.AppendLine();
            sb.Append("| ball |");
            foreach (double s in steps)
            {
                sb.Append(' ').Append(StepName(s)).Append(" s |");
            }

            sb.AppendLine();
            sb.Append("|---|").Append(string.Concat(Enumerable.Repeat("---|", steps.Length))).AppendLine();
            for (int b = 0; b < Scenarios.Balls.Length; b++)
            {
                sb.Append("| ").Append(Scenarios.Balls[b].Name).Append(" |");
                for (int si = 0; si < steps.Length; si++)
                {
                    sb.Append(' ').Append(worstError.TryGetValue((b, si), out double e) ? e.ToString("E1", Inv) : "-").Append(" |");
                }

                sb.AppendLine();
            }

            sb.AppendLine();
            sb.AppendLine($"Default stepping spent {defaultEvaluations:N0} derivative evaluations over the matrix.");
            return sb.ToString();
        }

        private static void Bump(Dictionary<(int, int), int> d, (int, int) key, bool condition)
        {
            d.TryGetValue(key, out int n);
            d[key] = n + (condition ? 1 : 0);
        }

        private static int Get(Dictionary<(int, int), int> d, (int, int) key) => d.TryGetValue(key, out int n) ? n : 0;

        public static string StepName(double step) =>
            step == 1e-4 ? "1e-4" : step < 0.09 ? "1/" + Math.Round(1 / step).ToString(Inv) : step.ToString("G", Inv);

        /// <summary>
        /// The step at which each raw integrator first makes the flight oscillate (the velocity reverses within one step)
        /// and first makes it diverge (speed grows beyond s0 + g t), found by bisection on log h, against 1/(k C_D s0).
        /// </summary>
        public static string BlowUp()
        {
            var sb = new StringBuilder();
            sb.AppendLine("Horizontal launch from 1 m, no spin, flown for up to 40 steps or 2 s. x = h k C_D s0 (k = rho A / 2m): the step in units of the drag time scale 1/(k C_D s0). Bisection on log h to 1 %.");
            sb.AppendLine();
            sb.AppendLine("| ball | s0 (m/s) | 1/(k C_D s0) (s) | method | oscillates at h (s) | x | diverges at h (s) | x |");
            sb.AppendLine("|---|---|---|---|---|---|---|---|");
            foreach (BallCase ball in Scenarios.Balls)
            {
                FlightModel model = ball.Model(Scenarios.G).WithLift(null).WithSpinDecay(null);
                double kcd = ball.DragRate(model);
                foreach (double s0 in new[] { 30.0, 100.0 })
                {
                    var launch = new FlightState(new Vector3d(0, 0, 1), new Vector3d(s0, 0, 0), default);
                    double scale = 1 / (kcd * s0);
                    foreach (IIntegrator integrator in Scenarios.FixedStepIntegrators)
                    {
                        double oscillates = Threshold(h => Oscillates(model, integrator, launch, h));
                        double diverges = Threshold(h => Diverges(model, integrator, launch, h));
                        sb.AppendLine($"| {ball.Name} | {s0} | {scale.ToString("G3", Inv)} | {integrator.Name} | {Fmt(oscillates)} | {Fmt(oscillates / scale)} | {Fmt(diverges)} | {Fmt(diverges / scale)} |");
                    }
                }
            }

            return sb.ToString();
        }

        private static string Fmt(double v) => double.IsPositiveInfinity(v) ? "> 2 s" : v.ToString("G3", Inv);

        private static double Threshold(Func<double, bool> fails)
        {
            double lo = 1e-5, hi = 2;
            if (!fails(hi))
            {
                return double.PositiveInfinity;
            }

            if (fails(lo))
            {
                return lo;
            }

            while (hi / lo > 1.01)
            {
                double mid = Math.Sqrt(lo * hi);
                if (fails(mid))
                {
                    hi = mid;
                }
                else
                {
                    lo = mid;
                }
            }

            return Math.Sqrt(lo * hi);
        }

        private static bool Oscillates(FlightModel model, IIntegrator integrator, FlightState state, double step)
        {
            var stepper = new FlightStepper(model, integrator);
            stepper.Reset(state);
            for (int i = 0; i < 40 && stepper.State.Time < 2; i++)
            {
                FlightState before = stepper.State;
                if (stepper.TryStep(step) != StepOutcome.Taken || stepper.State.Velocity.X * before.Velocity.X < 0)
                {
                    return true;
                }
            }

            return false;
        }

        private static bool Diverges(FlightModel model, IIntegrator integrator, FlightState state, double step)
        {
            double s0 = state.Velocity.Length, g = model.Gravity.Length;
            var stepper = new FlightStepper(model, integrator);
            stepper.Reset(state);
            for (int i = 0; i < 40 && stepper.State.Time < 2; i++)
            {
                // A step the core refuses (non-finite state or derivative) is a divergence, as is a run-away speed.
                if (stepper.TryStep(step) != StepOutcome.Taken || stepper.State.Velocity.Length > s0 + g * stepper.State.Time + 1e-9)
                {
                    return true;
                }
            }

            return false;
        }
    }
}
