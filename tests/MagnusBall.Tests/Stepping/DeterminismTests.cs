using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Stepping
{
    /// <summary>
    /// The same shot lands on the same bits whatever the frame rate, with the fixed-step driver; with the
    /// thesis's raw-delta stepping it does not.
    /// </summary>
    [TestFixture]
    public class DeterminismTests
    {
        private const double Step = 1.0 / 240;

        public static IEnumerable<TestCaseData> FrameSequences()
        {
            yield return new TestCaseData("30 FPS", DriverShots.FixedRate(30, 60)).SetArgDisplayNames("30 FPS");
            yield return new TestCaseData("60 FPS", DriverShots.FixedRate(60, 120)).SetArgDisplayNames("60 FPS");
            yield return new TestCaseData("144 FPS", DriverShots.FixedRate(144, 288)).SetArgDisplayNames("144 FPS");
            yield return new TestCaseData("jittery 5-50 ms", DriverShots.Jittery(20261124, 400)).SetArgDisplayNames("jittery 5-50 ms");
            yield return new TestCaseData("60 FPS, 0.5 s hitch", DriverShots.WithHitch(20, 400)).SetArgDisplayNames("60 FPS, 0.5 s hitch");
        }

        private static readonly (string Name, double[] Deltas)[] Sequences =
            FrameSequences().Select(c => ((string)c.Arguments[0]!, (double[])c.Arguments[1]!)).ToArray();

        public static IEnumerable<IIntegrator> DriverIntegrators() => Integrators.All.Append(StableIntegrator.RungeKutta4);

        [TestCaseSource(nameof(DriverIntegrators))]
        public void FixedStepDriver_LandsOnTheSameBits_AtEveryFrameRate(IIntegrator integrator)
        {
            FlightEvent reference = DriverShots.LandWithDriver(DriverShots.YUpTennis, integrator, Step, DriverShots.Drive, DriverShots.FixedRate(60, 1));
            foreach ((string name, double[] deltas) in Sequences)
            {
                FlightEvent landing = DriverShots.LandWithDriver(DriverShots.YUpTennis, integrator, Step, DriverShots.Drive, deltas);
                TestContext.Out.WriteLine($"{integrator.Name}, {name}: lands at {landing.Position} at t = {landing.Time:R} s");

                // Bitwise: Vector3d equality and double equality are exact, no tolerance.
                Assert.That(landing.Position, Is.EqualTo(reference.Position), name);
                Assert.That(landing.Time, Is.EqualTo(reference.Time), name);
                Assert.That(landing.State.Velocity, Is.EqualTo(reference.State.Velocity), name);
            }

            // The shot is a real one: it crosses the net line and lands in the far court.
            Assert.That(reference.Position.X, Is.InRange(12.0, 30.0));
        }

        [Test]
        public void RawDeltaStepping_AsInTheThesis_LandsInDifferentPlaces()
        {
            // The thesis stepped once per frame with Time.deltaTime, with RK4 (its default) or Euler.
            // Landings are located on the same cubic Hermite as the driver's, so only the stepping differs.
            double rk4 = 0, rk4NoHitch = 0, euler = 0, eulerNoHitch = 0;
            foreach (IIntegrator integrator in new IIntegrator[] { RungeKutta4.Instance, ExplicitEuler.Instance })
            {
                var landings = new List<Vector3d>();
                foreach ((string name, double[] deltas) in Sequences)
                {
                    Vector3d landing = DriverShots.LandWithRawDeltas(DriverShots.YUpTennis, integrator, DriverShots.Drive, deltas);
                    landings.Add(landing);
                    TestContext.Out.WriteLine($"raw delta, {integrator.Name}, {name}: lands at x = {landing.X:F9} m, z = {landing.Z:F9} m");
                }

                double spread = Spread(landings);
                double spreadNoHitch = Spread(landings.Take(4).ToList()); // frame-rate changes alone, steps <= 50 ms
                TestContext.Out.WriteLine($"raw delta, {integrator.Name}: landing spread {spread:G4} m with the hitch, {spreadNoHitch:G4} m without");
                if (integrator == RungeKutta4.Instance)
                {
                    (rk4, rk4NoHitch) = (spread, spreadNoHitch);
                }
                else
                {
                    (euler, eulerNoHitch) = (spread, spreadNoHitch);
                }
            }

            // If the landing is also taken as the first frame below the ground, as a per-frame game loop does,
            // the frame length itself moves the landing by up to a frame's travel.
            var firstFrame = Sequences.Select(s => FirstFrameBelowGround(RungeKutta4.Instance, s.Deltas)).ToList();
            double firstFrameSpread = Spread(firstFrame);
            TestContext.Out.WriteLine($"raw delta, rk4, landing = first frame below ground: spread {firstFrameSpread:G4} m");

            // Lower bounds about a quarter of the values measured when this test was written (docs/unity.md),
            // so they flag a real change, not round-off; the fixed-step driver's spread is exactly 0.
            Assert.That(eulerNoHitch, Is.GreaterThan(0.1), "Euler, frame rate alone (measured 0.41 m)");
            Assert.That(euler, Is.GreaterThan(1.0), "Euler with the hitch (measured 4.7 m)");
            Assert.That(rk4, Is.GreaterThan(1e-3), "RK4 with the hitch (measured 5.8 mm)");
            Assert.That(rk4NoHitch, Is.GreaterThan(1e-7), "RK4, frame rate alone (measured 0.46 um): small, but not bitwise equal");
            Assert.That(firstFrameSpread, Is.GreaterThan(0.04), "RK4, first frame below ground (measured 0.17 m)");
        }

        private static Vector3d FirstFrameBelowGround(IIntegrator integrator, double[] deltas)
        {
            FlightModel model = DriverShots.YUpTennis;
            FlightState state = DriverShots.Drive;
            for (int frame = 0; frame < 100_000; frame++)
            {
                state = integrator.Step(model, state, deltas[frame % deltas.Length]);
                if (state.Position.Y < 0)
                {
                    return state.Position;
                }
            }

            throw new InvalidOperationException("the ball did not land");
        }

        [Test]
        public void SameShots_OnSeveralThreadsAtOnce_GiveIdenticalResults()
        {
            FlightState[] shots =
            {
                DriverShots.Drive,
                DriverShots.Launch(45, -3, 0, 0, 0, 2.87),   // flat serve
                DriverShots.Launch(20, 25, -4, -8, 0),       // lob with backspin
                DriverShots.Launch(26, 12, 5, 35, -10),      // heavy topspin, curling
            };

            // Reference, single-threaded; the model and the integrator are shared by every driver below.
            FlightModel model = DriverShots.YUpTennis;
            Vector3d[] reference = shots.Select(s => DriverShots.LandWithDriver(model, RungeKutta4.Instance, Step, s, DriverShots.FixedRate(60, 1)).Position).ToArray();

            const int threadCount = 6;
            var results = new Vector3d[threadCount][];
            var failures = new Exception?[threadCount];
            using var start = new Barrier(threadCount);
            var threads = new Thread[threadCount];
            for (int t = 0; t < threadCount; t++)
            {
                int index = t;
                threads[t] = new Thread(() =>
                {
                    try
                    {
                        start.SignalAndWait();
                        double[] deltas = DriverShots.Jittery(1000 + index, 500); // every thread its own frame times
                        var mine = new Vector3d[shots.Length];
                        for (int repeat = 0; repeat < 3; repeat++)
                        {
                            for (int s = 0; s < shots.Length; s++)
                            {
                                mine[s] = DriverShots.LandWithDriver(model, RungeKutta4.Instance, Step, shots[s], deltas).Position;
                            }
                        }

                        results[index] = mine;
                    }
                    catch (Exception e)
                    {
                        failures[index] = e;
                    }
                });
                threads[t].Start();
            }

            foreach (Thread thread in threads)
            {
                thread.Join();
            }

            for (int t = 0; t < threadCount; t++)
            {
                Assert.That(failures[t], Is.Null, $"thread {t}");
                Assert.That(results[t], Is.EqualTo(reference), $"thread {t}: bitwise the same landings");
            }
        }

        private static double Spread(IReadOnlyList<Vector3d> points)
        {
            double max = 0;
            for (int i = 0; i < points.Count; i++)
            {
                for (int j = i + 1; j < points.Count; j++)
                {
                    max = Math.Max(max, Vector3d.Distance(points[i], points[j]));
                }
            }

            return max;
        }
    }
}
