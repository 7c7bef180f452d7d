using System;
using System.Collections.Generic;
using System.Text.Json;
using MagnusBall.Aerodynamics;
using MagnusBall.Queries;
using MagnusBall.Tests.Validation;

namespace MagnusBall.Tests.Queries
{
    /// <summary>
    /// The aim solves whose answers were recorded with the fixed-step solver (RK4 at 1/240 s trials, before the solver
    /// was rebuilt on adaptive trials): Cross (2011)'s four angles with Stepanek's and the thesis's coefficients (z-up,
    /// and the Stepanek ones in a y-up frame), Javorova &amp; Ivanov (2018)'s free kick (z-up and y-up), the benchmark's
    /// four solves on the full tennis model, a curving shot and a few unreachable ones. <see cref="AimRecordTests"/>
    /// holds the recorded answers.
    /// </summary>
    internal static class AimCases
    {
        /// <summary>Makes a solver for a model and a ground plane.</summary>
        public delegate AimSolver SolverFactory(FlightModel model, Plane ground);

        /// <summary>Every case, solved with solvers from <paramref name="make"/>, in a fixed order.</summary>
        public static List<(string Name, AimSolution Solution)> SolveAll(SolverFactory make)
        {
            var results = new List<(string, AimSolution)>();
            Cross(make, results);
            FreeKick(make, results, "freekick z-up", Vector3d.UnitZ, Vector3d.UnitX);
            FreeKick(make, results, "freekick y-up", Vector3d.UnitY, Vector3d.UnitX);
            Benchmark(make, results);
            return results;
        }

        // The tennis ball of Cross (2011) and the benchmarks, given explicitly (0.057 kg, 0.033 m) so the records do
        // not depend on the library's Ball.Tennis.
        private static readonly Ball TennisBall = new Ball(0.057, 0.033);

        private static void Cross(SolverFactory make, List<(string, AimSolution)> results)
        {
            JsonElement c = PublishedCases.Load("cross2011_tennis.json");
            var ball = new Ball(c.Number("ball", "mass_kg"), c.Number("ball", "radius_m"));
            var air = new Air(c.Number("air", "density_kgpm3"));
            double speed = c.Number("launch", "speed_mps");
            double height = c.Number("launch", "height_m");
            double netX = c.Number("net", "distance_m"), netHeight = c.Number("net", "height_m");
            double baselineX = c.Number("baseline", "distance_m");
            var topspin = new LaunchSpin(Spin.FromRevolutionsPerSecond(c.Number("topspin_revps")));

            // z-up (x downrange) and y-up (the z-up case rotated -90 degrees about x: (x, y, z) -> (x, z, -y)).
            foreach (bool yUp in new[] { false, true })
            {
                Vector3d up = yUp ? Vector3d.UnitY : Vector3d.UnitZ;
                Vector3d P(double x, double h) => Vector3d.UnitX * x + up * h;
                var models = new List<(string, FlightModel)>
                {
                    ("stepanek", new FlightModel(ball, air, Gravity.Along(up), StepanekDrag.Instance, StepanekLift.Instance)),
                };
                if (!yUp)
                {
                    models.Add(("thesis", new FlightModel(ball, air, Gravity.Along(up),
                        new ConstantDrag(c.Number("seed_thesis_coefficients", "cd")), new ConstantLift(c.Number("seed_thesis_coefficients", "cm")))));
                }

                foreach ((string name, FlightModel model) in models)
                {
                    AimSolver solver = make(model, Plane.Ground(model));
                    var net = new Plane(P(netX, 0), Vector3d.UnitX);
                    string prefix = $"cross {name} {(yUp ? "y-up" : "z-up")} ";
                    results.Add((prefix + "net_nospin", solver.MinimumElevationToClear(P(0, height), speed, 0, LaunchSpin.None, net, netHeight)));
                    results.Add((prefix + "baseline_nospin", solver.ElevationToReach(P(0, height), speed, LaunchSpin.None, P(baselineX, 0))));
                    results.Add((prefix + "net_topspin", solver.MinimumElevationToClear(P(0, height), speed, 0, topspin, net, netHeight)));
                    results.Add((prefix + "baseline_topspin", solver.ElevationToReach(P(0, height), speed, topspin, P(baselineX, 0))));
                }
            }
        }

        private static void FreeKick(SolverFactory make, List<(string, AimSolution)> results, string name, Vector3d up, Vector3d forward)
        {
            // As FreeKickTests.Run: Goff & Carre drag and lift, the ball on the pitch (centre one radius up), pure sidespin.
            JsonElement j = PublishedCases.Load("javorova2018_freekick.json");
            var ball = new Ball(j.Number("ball", "mass_kg"), j.Number("ball", "radius_m"), Ball.ThinShellInertiaFactor);
            var model = new FlightModel(ball, new Air(1.21), Gravity.Along(up), GoffCarreSoccerDrag.Instance, PiecewiseLinearLift.SoccerGoffCarre);
            Vector3d side = new LaunchFrame(up, forward).Side;
            Vector3d start = up * ball.Radius;
            var ground = new Plane(start, up);
            Vector3d target = forward * j.Number("goal_line_distance_m") + side * j.Number("target_at_goal_line", "lateral_m")
                + up * j.Number("target_at_goal_line", "height_m");
            var spin = new LaunchSpin(0, j.Number("spin_radps"));
            double speed = j.GetProperty("speeds_mps")[1].GetDouble();
            results.Add((name, make(model, ground).AnglesToReach(start, speed, spin, target)));
        }

        private static void Benchmark(SolverFactory make, List<(string, AimSolution)> results)
        {
            // The benchmark's full tennis model (Workloads.cs): Stepanek drag and lift, spin decay tau 20 s, rho 1.21.
            var model = new FlightModel(TennisBall, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            AimSolver solver = make(model, Plane.Ground(model));
            var start = new Vector3d(0, 0, 1);
            var spin = new LaunchSpin(Spin.FromRevolutionsPerSecond(20));
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            results.Add(("bench clear net", solver.MinimumElevationToClear(start, 30, 0, spin, net, 0.914)));
            results.Add(("bench baseline", solver.ElevationToReach(start, 30, spin, new Vector3d(23.77, 0, 0))));
            results.Add(("bench corner", solver.AnglesToReach(start, 30, spin, new Vector3d(23.77, 4.1, 0))));
            results.Add(("bench speed", solver.SpeedToReach(start, 8 * Math.PI / 180, 0, spin, new Vector3d(23.77, 0, 0))));

            // A curving shot (AimSolverTests), elevation with an azimuth, a speed with sidespin and azimuth, a backspin
            // float, a lob over a high net and the unreachable ones.
            var curl = new LaunchSpin(Spin.FromRpm(1500), Spin.FromRpm(1200));
            results.Add(("curve angles", solver.AnglesToReach(start, 28, curl, new Vector3d(20, -2, 1.5))));
            results.Add(("curve elevation az 3deg", solver.ElevationToReach(start, 28, curl, new Vector3d(20, -2, 1.5), 3 * Math.PI / 180)));
            results.Add(("curve speed", solver.SpeedToReach(start, 12 * Math.PI / 180, -2 * Math.PI / 180, curl, new Vector3d(18, 1, 0))));
            results.Add(("backspin float", solver.ElevationToReach(start, 22, LaunchSpin.Backspin(Spin.FromRpm(2500)), new Vector3d(21, 0, 0))));
            results.Add(("high net", solver.MinimumElevationToClear(start, 25, 0.1, spin, net, 4)));
            results.Add(("serve down", solver.ElevationToReach(new Vector3d(0, 0, 2.8), 50, new LaunchSpin(Spin.FromRpm(800)), new Vector3d(18.3, 1, 0))));
            results.Add(("too far", solver.ElevationToReach(start, 12, spin, new Vector3d(40, 0, 0))));
            results.Add(("too far angles", solver.AnglesToReach(start, 12, spin, new Vector3d(40, 3, 0))));
            results.Add(("too high", solver.MinimumElevationToClear(start, 10, 0, spin, net, 30)));
            results.Add(("speed too steep down", solver.SpeedToReach(start, -30 * Math.PI / 180, 0, spin, new Vector3d(20, 0, 5))));
        }
    }
}
