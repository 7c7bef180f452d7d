using System;
using System.Collections.Generic;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Robustness
{
    /// <summary>
    /// A fast subset of the extremes matrix (the full one runs in the benchmark project: `extremes` mode, table in
    /// docs/integrators.md). Every ball at every speed, the hardest spins, frame and hitch steps.
    /// </summary>
    [TestFixture]
    public class ExtremesMatrixTests
    {
        private static readonly double[] Speeds = { 0, 1e-3, 1, 30, 70, 100 };
        private static readonly (double Rate, string Orientation)[] Spins = { (0, "along"), (1000, "along"), (500, "across"), (1000, "oblique") };

        // The stated bounds on the default stepping's landing error (RK4 through StableStepping, landing on the step's
        // cubic Hermite), per step: the full matrix's worst case over all 360 cells of that step (docs/integrators.md:
        // 1.4e-4 m at 1/240 s, 2.9e-3 m at 1/60 s, 9.9e-3 m at 0.1 s, 3.2e-2 m at 0.25 s) rounded up by a factor of about 3.
        private static readonly (double Step, double Bound)[] Steps = { (1.0 / 240, 5e-4), (1.0 / 60, 1e-2), (0.1, 3e-2), (0.25, 0.1) };

        public static IEnumerable<TestCaseData> BallsAndSteps()
        {
            for (int b = 0; b < ExtremeCases.Balls.Length; b++)
            {
                foreach ((double step, double bound) in Steps)
                {
                    yield return new TestCaseData(b, step, bound).SetName($"DefaultStepping_{ExtremeCases.Balls[b].Name.Replace(' ', '_')}_step{step:G3}");
                }
            }
        }

        [TestCaseSource(nameof(BallsAndSteps))]
        public void DefaultStepping_StaysFiniteLosesEnergyAndLandsNearTheReference(int ball, double step, double bound)
        {
            (string name, FlightModel model) = ExtremeCases.Balls[ball];
            double worst = 0;
            foreach (double speed in Speeds)
            {
                foreach ((double rate, string orientation) in Spins)
                {
                    FlightState launch = ExtremeCases.Launch(speed, rate, orientation);
                    ExtremeCases.Outcome o = ExtremeCases.Fly(model, RungeKutta4.Instance, launch, step);
                    string cell = $"{name} {speed} m/s {rate} rad/s {orientation} at {step:G4} s";
                    Assert.That(o.Finite, Is.True, cell + ": finite");
                    Assert.That(o.Diverged, Is.False, cell + ": speed never exceeds s0 + g t");
                    // 1e-12 of the energy scale m (v^2/2 + g |p| + g): rounding of the energy sum itself; without wind,
                    // drag only removes energy and Magnus lift does no work.
                    Assert.That(o.MaxEnergyRise, Is.LessThanOrEqualTo(1e-12), cell + ": energy never rises");
                    Assert.That(o.Landed, Is.True, cell + ": lands");
                    double error = Vector3d.Distance(o.Landing, ExtremeCases.ReferenceLanding(model, launch));
                    worst = Math.Max(worst, error);
                    Assert.That(error, Is.LessThan(bound), cell + ": landing error (m)");
                }
            }

            TestContext.Out.WriteLine($"{name} at {step:G4} s: worst landing error {worst:E2} m");
        }

        [Test]
        public void EveryIntegrator_ThroughStableStepping_StaysBoundedInAQuarterSecondHitch()
        {
            IIntegrator[] integrators = { ExplicitEuler.Instance, SemiImplicitEuler.Instance, Heun.Instance, RungeKutta4.Instance, DormandPrince54.Instance };
            foreach ((string name, FlightModel model) in ExtremeCases.Balls)
            {
                foreach (IIntegrator integrator in integrators)
                {
                    FlightState launch = ExtremeCases.Launch(100, 1000, "oblique");
                    ExtremeCases.Outcome o = ExtremeCases.Fly(model, integrator, launch, 0.25);
                    Assert.That(o.Finite && !o.Diverged && o.Landed, Is.True, $"{integrator.Name}, {name} at 100 m/s, 0.25 s steps");
                }
            }
        }

        [Test]
        public void RawRk4_DivergesWhereStableSteppingDoesNot()
        {
            // The point of the criterion: a light, fast ball and a hitch-sized step. 1/(k C_D s) = 0.021 s for the
            // beach ball at 100 m/s; raw RK4 diverges beyond about 2.45 times that (measured, docs/integrators.md).
            (string _, FlightModel model) = ExtremeCases.Balls[5];
            FlightState launch = ExtremeCases.Launch(100, 0, "along");
            StateDerivative k1 = model.Derivative(launch);
            FlightState raw = ((IIntegrator)RungeKutta4.Instance).Step(model, launch, k1, 0.25);
            FlightState safe = StableStepping.Step(RungeKutta4.Instance, model, launch, k1, 0.25, out _, out int substeps);

            Assert.That(raw.Velocity.Length, Is.GreaterThan(100), "raw RK4 gains speed from drag: unstable");
            Assert.That(safe.Velocity.Length, Is.LessThan(10), "a beach ball sheds 100 m/s to near its ~4.6 m/s terminal speed in 0.25 s");
            Assert.That(substeps, Is.GreaterThan(1).And.LessThan(100));
            Assert.That(safe.Time, Is.EqualTo(0.25));
        }
    }
}
