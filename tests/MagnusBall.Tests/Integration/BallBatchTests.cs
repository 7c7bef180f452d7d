using System;
using System.Collections.Generic;
using System.Numerics;
using MagnusBall.Aerodynamics;
using MagnusBall.Batch;
using MagnusBall.Integration;
using MagnusBall.Flight;
using NUnit.Framework;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Tests.Integration
{
    /// <summary>
    /// The batch of balls against the single-ball path (a <see cref="FlightStepper"/> with RK4 and a ground event, one
    /// ball at a time): the same states every frame and the same landings, for vectorised and ball-by-ball models.
    /// </summary>
    [TestFixture]
    public class BallBatchTests
    {
        // The brief's bound: 1e-12 relative. The batch computes the same IEEE operations in the same order in every lane,
        // so it is in fact exact; the test asserts the stated bound and reports the largest difference seen.
        private const double Relative = 1e-12;

        public static IEnumerable<TestCaseData> Models()
        {
            Vector3d g = Gravity.ZUp;
            yield return new TestCaseData(new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(2, -1, 0)), g,
                StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)), true).SetName("FullTennisWindy");
            yield return new TestCaseData(FlightModel.Thesis(Ball.Tennis, new Air(1.21), g), true).SetName("Thesis");
            yield return new TestCaseData(new FlightModel(Ball.Tennis, new Air(1.21), g, ConstantDrag.CrossLindseyTennis, LinearSpinLift.Cross2020Tennis), true)
                .SetName("CrossLinearLift");
            yield return new TestCaseData(FlightModel.Vacuum(Ball.Tennis, g), true).SetName("Vacuum");
            yield return new TestCaseData(new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(2, -1, 0)), g, ConstantDrag.CrossLindseyTennis), true)
                .SetName("ConstantDragOnly");
            yield return new TestCaseData(new FlightModel(Ball.Soccer, new Air(1.2).WithLogarithmicWind(new Vector3d(5, 0, 0)), g,
                GoffCarreSoccerDrag.Instance, PiecewiseLinearLift.SoccerGoffCarre), false).SetName("SoccerWindProfile_BallByBall");
        }

        private static FlightState[] Starts(int count)
        {
            var random = new Random(3);
            var starts = new FlightState[count];
            for (int i = 0; i < count; i++)
            {
                double speed = 15 + 30 * random.NextDouble();
                double elevation = (20 * random.NextDouble() - 5) * Math.PI / 180;
                double height = i == 0 ? 0 : 0.3 + random.NextDouble(); // ball 0 starts on the ground
                starts[i] = new FlightState(
                    new Vector3d(0, 0, height),
                    new Vector3d(speed * Math.Cos(elevation), 2 * random.NextDouble() - 1, i == 0 ? -1 : speed * Math.Sin(elevation)), // ball 0 heads into the ground
                    new Vector3d(50 * random.NextDouble() - 25, 300 * random.NextDouble() - 100, 30 * random.NextDouble() - 15),
                    random.NextDouble());
            }

            return starts;
        }

        [TestCaseSource(nameof(Models))]
        public void EveryFrameAndLanding_EqualsTheSingleBallPath(FlightModel model, bool vectorLaws)
        {
            // Also one call of four steps against four calls of one (apart): Advance(step, 4) runs each ball through its four
            // steps before the next ball where the batch goes ball by ball, and lane group by lane group, step by step, where
            // it is vectorised; either way the same numbers, bit for bit, and the single-ball path's, bit for bit too (the
            // stated bound below is the brief's; the batch is in fact exact).
            const int count = 37; // not a multiple of the vector width: padding lanes
            FlightState[] starts = Starts(count);
            var batch = new BallBatch(model, count);
            var apart = new BallBatch(model, count);
            Assert.That(batch.IsVectorized, Is.EqualTo(vectorLaws && Vector.IsHardwareAccelerated));
            var steppers = new FlightStepper[count];
            var landed = new bool[count];
            var landings = new FlightState[count];
            var ground = Plane.Ground(model);
            var events = new FlightEventSet(model.Up, ground);
            for (int i = 0; i < count; i++)
            {
                Assert.That(batch.Add(starts[i]), Is.EqualTo(i));
                apart.Add(starts[i]);
                steppers[i] = new FlightStepper(model, RungeKutta4.Instance, events);
                steppers[i].Reset(starts[i]);
            }

            double worst = 0;
            for (int frame = 0; frame < 300; frame++)
            {
                batch.Advance(1.0 / 240, 4);
                for (int s = 0; s < 4; s++)
                {
                    apart.Advance(1.0 / 240);
                }

                for (int i = 0; i < count; i++)
                {
                    AssertSameBall(batch, apart, i, $"{model}, frame {frame}: one call of four steps against four of one");
                    for (int s = 0; s < 4 && !landed[i]; s++)
                    {
                        StepOutcome outcome = steppers[i].TryStep(1.0 / 240, FlightEventKinds.Landing);
                        Assert.That(outcome == StepOutcome.Taken || outcome == StepOutcome.Stopped, Is.True, $"ball {i}: {outcome}");
                        if (steppers[i].TryGetEvent(FlightEventKinds.Landing, out FlightEvent landing))
                        {
                            Assert.That(outcome, Is.EqualTo(StepOutcome.Stopped));
                            landed[i] = true;
                            landings[i] = landing.State;
                        }
                    }

                    FlightState expected = landed[i] ? landings[i] : steppers[i].State;
                    worst = Math.Max(worst, Difference(batch.GetState(i), expected));
                    Assert.That(Difference(batch.GetState(i), expected), Is.EqualTo(0), $"{model}, frame {frame}, ball {i}: the single-ball path");
                    Assert.That(batch.IsFlying(i), Is.EqualTo(!landed[i]), $"ball {i}, frame {frame}");
                    Assert.That(batch.TryGetLanding(i, out FlightState batchLanding), Is.EqualTo(landed[i]));
                    if (landed[i])
                    {
                        worst = Math.Max(worst, Difference(batchLanding, landings[i]));
                    }
                }
            }

            TestContext.WriteLine($"largest relative difference {worst:E2}");
            Assert.That(worst, Is.LessThanOrEqualTo(Relative));
            Assert.That(Array.TrueForAll(landed, x => x), Is.True, "every ball lands within 5 s");
            Assert.That(batch.TryGetLanding(0, out FlightState first) && first.Time == starts[0].Time, Is.True, "ball 0 lands at once");
        }

        [Test]
        public void Frame_AllocatesZeroBytes()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            FlightState[] starts = Starts(1000);
            var batch = new BallBatch(model, 1000);
            int flying = 0;
            Action frames = () =>
            {
                // The same 1,000 balls from their starts every run (a run that found them landed would do nothing).
                batch.Clear();
                for (int i = 0; i < starts.Length; i++)
                {
                    batch.Add(starts[i]);
                }

                for (int frame = 0; frame < 100; frame++)
                {
                    batch.Advance(1.0 / 240, 4); // landings included: most balls land within these 100 frames
                }

                flying = 0;
                for (int i = 0; i < batch.Count; i++)
                {
                    flying += batch.IsFlying(i) ? 1 : 0;
                }
            };

            long allocated = Allocation.SteadyStateBytes(frames);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(flying, Is.LessThan(500), "most balls landed in the measured frames");
        }

        [Test]
        public void BadInput_IsRefusedAndChangesNothing()
        {
            var model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            Assert.Throws<ArgumentOutOfRangeException>(() => new BallBatch(model, 0));
            Assert.Throws<ArgumentNullException>(() => new BallBatch(null!, 10));
            var batch = new BallBatch(model, 2);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 5), new Vector3d(0, 100, 0));
            batch.Add(start);
            Assert.Throws<ArgumentException>(() => batch.Add(new FlightState(new Vector3d(double.NaN, 0, 0), default, default)));
            Assert.That(batch.Count, Is.EqualTo(1));
            Assert.Throws<ArgumentOutOfRangeException>(() => batch.Advance(0));
            Assert.Throws<ArgumentOutOfRangeException>(() => batch.Advance(double.NaN));
            Assert.Throws<ArgumentOutOfRangeException>(() => batch.Advance(0.01, -1));
            Assert.Throws<ArgumentOutOfRangeException>(() => batch.GetState(1));
            Assert.That(batch.GetState(0).Position, Is.EqualTo(start.Position));
            batch.Add(start);
            Assert.Throws<InvalidOperationException>(() => batch.Add(start));
        }

        [Test]
        public void BallsSpinningPast1e154_FlyAsTheSingleBallPath_BitForBit()
        {
            // The vector lanes take |w| as a plain square root of the squares, which overflows past about 1.3e154 rad/s where
            // the kernel scales first: the thesis model's ball then flew without lift and Stepanek's was stopped as
            // diverged. Such a vector now takes the per-ball kernel step; its neighbours in the vector are unchanged
            // (they equal the single-ball path either way).
            var ground = new Plane(new Vector3d(0, 0, -1e6), Vector3d.UnitZ);
            foreach (FlightModel model in new[]
            {
                FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance),
            })
            {
                var starts = new[]
                {
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 1e160, 0)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(25, -2, 8), new Vector3d(10, 150, 20)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(3e200, -4e200, 1e155)),
                };
                (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts);

                for (int step = 0; step < 24; step++)
                {
                    batch.Advance(1.0 / 240);
                    for (int i = 0; i < starts.Length; i++)
                    {
                        Assert.That(steppers[i].TryStep(1.0 / 240, FlightEventKinds.Landing), Is.EqualTo(StepOutcome.Taken), $"{model}, ball {i}, step {step}");
                        Assert.That(batch.HasDiverged(i), Is.False, $"{model}, ball {i}, step {step}");
                        Assert.That(Difference(batch.GetState(i), steppers[i].State), Is.EqualTo(0), $"{model}, ball {i}, step {step}");
                    }
                }
            }
        }

        [Test]
        public void BallsOutsideTheStepanekFold_FlyAsTheSingleBallPath_BitForBit()
        {
            // The kernel folds Stepanek's lift (and drag) only within a range of |w|, s^2 and |w x v|^2; outside it, the general
            // formula. The lanes compute the fold: a ball outside its range takes the per-ball kernel step, its neighbours in
            // the vector keep theirs (all equal to the single-ball path).
            var ground = new Plane(new Vector3d(0, 0, -1e6), Vector3d.UnitZ);
            foreach (FlightModel model in new[]
            {
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                new FlightModel(Ball.Tennis, new Air(1.1, new Vector3d(3, -2, 0.5)), Gravity.ZUp, ConstantDrag.CrossLindseyTennis, StepanekLift.Instance),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, null, StepanekLift.Instance),
            })
            {
                Vector3d wind = model.Air.Wind;
                var starts = new[]
                {
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 1e-60, 0)),          // |w| below 1e-50
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(25, -2, 8), new Vector3d(10, 150, 20)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 3e50, 1)),           // |w| past 1e50
                    new FlightState(new Vector3d(0, 0, 1), wind + new Vector3d(30, 0, 0), new Vector3d(1, 1e-110, 0)), // |w x v|^2 below 1e-200
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 3, 9), new Vector3d(-40, 200, 5)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(2e100, 1, 5), new Vector3d(-4.56, -6.41, -0.157)),       // s^2 past 1e200
                    new FlightState(new Vector3d(0, 0, 1), wind + new Vector3d(3e-101, 0, 1e-101), new Vector3d(10, 150, 20)),  // s^2 below 1e-200
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(1e60, 0, 0), new Vector3d(0, 1e45, 0)),                 // |w x v|^2 past 1e200
                };
                (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts);

                // A step short enough that the fastest balls change their velocity little (drag about 1e198 m/s^2 at 2e100 m/s).
                AssertFlyAlike(batch, steppers, 1e-110, 8, model.ToString());
            }
        }

        [Test]
        public void Lanes_GiveTheKernelsRates_BitForBit()
        {
            // The lanes' rates (VectorLaws.Rates) against the kernel's (FlightModel.Derivative), lane by lane, where a step's
            // state alone would hide a last-bit difference (a drag of 1e-145 m/s^2 on a ball at 1e-147 m/s changes no
            // velocity bit). States: ordinary drives, balls whose z sits at the edges of Stepanek's table, spinless balls and
            // spins at or below FlightModel.MinimumLiftSpinRate (no lift: the kernel's general formula), at tiny speeds
            // where z lies inside the table, and a 100 m ball. Lanes the batch marks for the per-ball step are skipped.
            var random = new Random(23);
            int compared = 0;
            foreach (Ball ball in new[] { Ball.Tennis, new Ball(0.057, 100) })
            {
                foreach (FlightModel model in new[]
                {
                    new FlightModel(ball, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                    new FlightModel(ball, new Air(1.21, new Vector3d(2, -1, 0)), Gravity.ZUp, null, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                    new FlightModel(ball, new Air(1.21), Gravity.ZUp, ConstantDrag.CrossLindseyTennis, StepanekLift.Instance),
                    new FlightModel(ball, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, ConstantLift.ThesisTennis, new ExponentialSpinDecay(20)),
                    new FlightModel(ball, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, null),
                })
                {
                    VectorLaws laws = VectorLaws.For(model);
                    Assert.That(laws.Supported, Is.True, model.ToString());
                    int width = Vector<double>.Count;
                    var states = new FlightState[width];
                    for (int round = 0; round < 100; round++)
                    {
                        for (int lane = 0; lane < width; lane++)
                        {
                            states[lane] = LaneState(random, ball.Radius);
                        }

                        double[] Component(Func<FlightState, double> pick)
                        {
                            var values = new double[width];
                            for (int lane = 0; lane < width; lane++)
                            {
                                values[lane] = pick(states[lane]);
                            }

                            return values;
                        }

                        laws.Rates(
                            new Vector<double>(Component(x => x.Velocity.X)), new Vector<double>(Component(x => x.Velocity.Y)), new Vector<double>(Component(x => x.Velocity.Z)),
                            new Vector<double>(Component(x => x.AngularVelocity.X)), new Vector<double>(Component(x => x.AngularVelocity.Y)), new Vector<double>(Component(x => x.AngularVelocity.Z)),
                            out Vector<double> ax, out Vector<double> ay, out Vector<double> az, out Vector<double> sx, out Vector<double> sy, out Vector<double> sz, out Vector<long> unfolded);
                        for (int lane = 0; lane < width; lane++)
                        {
                            if (unfolded[lane] != 0)
                            {
                                continue;
                            }

                            StateDerivative expected = FlightKernel.DerivativeOf(model, states[lane]);
                            string where = $"{model}, v {states[lane].Velocity}, w {states[lane].AngularVelocity}";
                            Assert.That(new Vector3d(ax[lane], ay[lane], az[lane]), Is.EqualTo(expected.Acceleration), where);
                            Assert.That(new Vector3d(sx[lane], sy[lane], sz[lane]), Is.EqualTo(expected.AngularAcceleration), where);
                            compared++;
                        }
                    }
                }
            }

            // 1,000 lanes a lane width (2 ball sizes x 5 models x 100 rounds); some are marked for the per-ball step.
            TestContext.WriteLine($"{compared} lanes compared");
            Assert.That(compared, Is.GreaterThan(750 * Vector<double>.Count), "lanes compared");

            static FlightState LaneState(Random random, double radius)
            {
                Vector3d direction = new Vector3d(random.NextDouble() - 0.3, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                Vector3d axis = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                direction /= direction.Length;
                axis /= axis.Length;
                double speed, spin;
                switch (random.Next(4))
                {
                    case 0: // a drive
                        speed = 5 + 60 * random.NextDouble();
                        spin = 600 * random.NextDouble();
                        break;
                    case 1: // z = Kappa s^2 / (r |w|)^2 near an edge of the table (2^-44 or 2^44)
                        speed = 30;
                        double z = (random.Next(2) == 0 ? 1.0 / 17592186044416.0 : 17592186044416.0) * (0.998 + 0.004 * random.NextDouble());
                        spin = speed * Math.Sqrt(StepanekTable.Kappa / z) / radius;
                        break;
                    case 2: // no lift, z inside the table: tiny speeds
                        spin = random.Next(3) == 0 ? 0 : 1e-150 * (0.5 + 0.5 * random.NextDouble());
                        speed = 1.01e-150 * Math.Pow(10, 4 * random.NextDouble());
                        break;
                    default: // no lift, ordinary speeds
                        spin = random.Next(2) == 0 ? 0 : 1e-151;
                        speed = 30 * random.NextDouble() + 1;
                        break;
                }

                return new FlightState(new Vector3d(0, 0, 1), direction * speed, axis * spin);
            }
        }

        [Test]
        public void DecayingSpinsAcrossTheFoldsEdges_FlyAsTheSingleBallPath_BitForBit()
        {
            // With Stepanek's lift and an exponential decay, a stage whose spin rate lies outside the fold's range takes the
            // general formula, so the batch must send that ball to the per-ball step even where its end rate lies inside.
            // Here h = tau/5: the inner stage spins are about 0.9, 0.91 and 0.818 of the step's and the end's about 0.819, so
            // a spin of 1.15e50 rad/s puts the first two stages above 1e50 and the last and the end below it; its neighbours
            // fly ordinary spins. The same for a spin just above the fold's lower edge (its inner stages cross 1e-50).
            var ground = new Plane(new Vector3d(0, 0, -1e300), Vector3d.UnitZ);
            foreach (Vector3d gravity in new[] { Vector3d.Zero, Gravity.ZUp })
            {
                var model = new FlightModel(Ball.Tennis, new Air(1.21), gravity, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(0.1));
                var starts = new[]
                {
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 1.15e50, 0)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(25, -2, 8), new Vector3d(10, 150, 20)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 1.15e-50, 0)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 3, 9), new Vector3d(-40, 200, 5)),
                };
                (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts);
                AssertFlyAlike(batch, steppers, 0.02, 6, gravity.ToString());
            }
        }

        [Test]
        public void BallsAtTheEdgesOfStepaneksTable_FlyAsTheSingleBallPath_BitForBit()
        {
            // Stepanek's drag reads its term G from a table where z = Kappa s^2 / (r |w|)^2 lies in [2^-44, 2^44) and from the
            // power elsewhere; the lanes call the same function per lane, the kernel's folded path (Stepanek's lift) forms z
            // from s^2 and the general path (constant lift) from u = s / (r |w|). Balls at 30 m/s with spins that put z just
            // inside and outside both edges, and in the middle, fly 40 steps of 1 s. In one step the drag alone would take
            // about the whole speed (k C_D s h near 0.9, inside RK4's stability limit of 2.8), so a change of G in its last bit
            // reaches the velocity's bits (with 0.05 s steps it did not: a z formed as (s^2 Kappa) / (r |w|)^2 passed); the
            // speed falls about thirty-fold, so z moves and the edge balls cross the edges. A lane that formed z differently from
            // the kernel, or read G through u as the general path does, fails at step 2 or sooner (both checked).
            var ground = new Plane(new Vector3d(0, 0, -1e6), Vector3d.UnitZ);
            double kappa = StepanekTable.Kappa;
            foreach (FlightModel model in new[]
            {
                new FlightModel(Ball.Tennis, new Air(1.21), Vector3d.Zero, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                new FlightModel(Ball.Tennis, new Air(1.21), Vector3d.Zero, StepanekDrag.Instance, ConstantLift.ThesisTennis, new ExponentialSpinDecay(20)),
            })
            {
                double r = model.Ball.Radius;
                const double speed = 30;
                var starts = new List<FlightState>();
                foreach (double z in new[] { 1.0 / 17592186044416.0, 17592186044416.0, 0.5, 1.0, 2.0, 5.0, 40.0 }) // 2^-44 and 2^44, the edges
                {
                    foreach (double factor in new[] { 0.999, 1.0, 1.001 })
                    {
                        // v along x, w about y: z = Kappa s^2 / (r |w|)^2 (|w| from 1.1e-4 to 1.9e9 rad/s).
                        double spin = speed * Math.Sqrt(kappa / (z * factor)) / r;
                        starts.Add(new FlightState(new Vector3d(0, 0, 1), new Vector3d(speed, 0, 1), new Vector3d(0.01 * spin, spin, 0)));
                    }
                }

                (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts.ToArray());
                AssertFlyAlike(batch, steppers, 1.0, 40, model.ToString());
            }
        }

        [Test]
        public void StepanekLiftModelsOutsideTheFoldsScale_FlyAsTheSingleBallPath_BitForBit()
        {
            // k below 1e-50 (air 3.135e-49 kg/m^3 as dense: k = 0.94e-50 1/m for a tennis ball): the kernel takes the general
            // formula for every ball of such a model, and so must the lanes. Speeds near 5e49 m/s and 0.1 s steps make the
            // forces change the velocity by a few per cent a step; no gravity, so nothing else does. The starts are states
            // where the folded form's bits differ from the general formula's at k = 1.19e-50, just inside the fold's range
            // (found by a search), so a lane that folded would show.
            var ground = new Plane(new Vector3d(0, 0, -1e300), Vector3d.UnitZ);
            var model = new FlightModel(Ball.Tennis, new Air(3.135e-49), Vector3d.Zero, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            Assert.That(model.AerodynamicFactor, Is.LessThan(1e-50));
            var starts = new[]
            {
                new FlightState(new Vector3d(0, 0, 1), new Vector3d(-1.1506801995324246E+49, 1.101084472096549E+49, 2.4102073507546406E+49), new Vector3d(1.152351258192629E+48, -6.085035949312667E+48, -4.758783961751855E+48)),
                new FlightState(new Vector3d(0, 0, 1), new Vector3d(-2.507080427834418E+49, -1.989129440135333E+49, 4.159942259413386E+49), new Vector3d(3.5630169805268353E+48, -8.58217155859816E+48, -7.6359455051497E+48)),
                new FlightState(new Vector3d(0, 0, 1), new Vector3d(-3.9808074956279457E+49, 3.756607054540954E+49, 4.0087540210231514E+49), new Vector3d(-9.820069917378971E+47, 2.9017579938172886E+47, -3.7377287745115703E+45)),
                new FlightState(new Vector3d(0, 0, 1), new Vector3d(6.404858315238771E+47, -7.884504794068741E+49, 6.237499811898652E+49), new Vector3d(2.1457816338194203E+47, -1.0352058121443571E+48, 4.959291342756368E+48)),
                new FlightState(new Vector3d(0, 0, 1), new Vector3d(-1.1703376493905467E+49, 1.1042652817864769E+49, 3.971815008195981E+48), new Vector3d(2.89822835683202E+48, 3.530469010931921E+48, 1.2436885618514774E+48)),
                new FlightState(new Vector3d(0, 0, 1), new Vector3d(-5.541478662100267E+49, -3.2264014080372545E+49, 2.0439078925985122E+49), new Vector3d(-2.3294398791553726E+48, -4.527804766541992E+48, -1.6239609330333083E+48)),
            };
            (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts);
            AssertFlyAlike(batch, steppers, 0.1, 8, model.ToString());
        }

        [Test]
        public void BallsFasterThan1e154_FlyAsTheSingleBallPath_BitForBit()
        {
            // The vector lanes take the speed as a plain square root of the squares, which overflows past about 1.34e154
            // m/s where the kernel scales first: the lane's rates were infinite and the ball was stopped as diverged
            // where the single-ball step is finite (a step short enough that the drag, about 3.9e306 m/s^2 at 1.4e154
            // m/s, changes the velocity little: 1e-160 s). Such a lane now takes the kernel's step; its neighbours are
            // unchanged. At 1e200 m/s both paths diverge at once.
            var ground = new Plane(new Vector3d(0, 0, -1e300), Vector3d.UnitZ);
            foreach (FlightModel model in new[]
            {
                FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
            })
            {
                var starts = new[]
                {
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(1.4e154, 1, 5), new Vector3d(0, 100, 0)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(25, -2, 8), new Vector3d(10, 150, 20)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(-3e154, 1e154, 2e154), new Vector3d(10, 150, 20)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(1e200, 1, 5), new Vector3d(0, 100, 0)),
                };
                (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts);

                const double step = 1e-160;
                for (int n = 0; n < 8; n++)
                {
                    batch.Advance(step);
                    for (int i = 0; i < starts.Length; i++)
                    {
                        StepOutcome outcome = steppers[i].TryStep(step, FlightEventKinds.Landing);
                        Assert.That(outcome, Is.EqualTo(i == 3 ? StepOutcome.Diverged : StepOutcome.Taken), $"{model}, ball {i}, step {n}");
                        Assert.That(batch.HasDiverged(i), Is.EqualTo(i == 3), $"{model}, ball {i}, step {n}");
                        Assert.That(Difference(batch.GetState(i), steppers[i].State), Is.EqualTo(0), $"{model}, ball {i}, step {n}");
                    }
                }
            }
        }

        [Test]
        public void DecayingSpinWhoseStagesPass1e154_FliesAsTheSingleBallPath_BitForBit()
        {
            // The batch checks the start spin's squares; with an exponential decay and a step of ten time constants, RK4's
            // stage spins grow (w (1 - h / 2 tau) = -4 w, then 21 w and -209 w), so from a start spin of 5e152 rad/s a
            // stage spin passed 1.34e154 rad/s: on a constant C_L the lane's 1/|w| was 0 there and the step flew partly
            // without lift (v.x 18.806 against the single-ball 19.025 m/s after one step). Such a lane now takes the
            // kernel's step.
            var ground = new Plane(new Vector3d(0, 0, -1e300), Vector3d.UnitZ);
            foreach (FlightModel model in new[]
            {
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, new ConstantDrag(0.55), new ConstantLift(0.175), new ExponentialSpinDecay(0.1)),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(0.1)),
            })
            {
                var starts = new[]
                {
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 5e152, 0)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(25, -2, 8), new Vector3d(10, 150, 20)),
                    new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(3e151, -4e151, 1e150)),
                };
                (BallBatch batch, FlightStepper[] steppers) = BatchAndSteppers(model, ground, starts);

                var diverged = new bool[starts.Length];
                for (int n = 0; n < 3; n++)
                {
                    batch.Advance(1.0);
                    for (int i = 0; i < starts.Length; i++)
                    {
                        StepOutcome outcome = diverged[i] ? StepOutcome.Diverged : steppers[i].TryStep(1.0, FlightEventKinds.Landing);
                        if (n == 0)
                        {
                            Assert.That(outcome, Is.EqualTo(StepOutcome.Taken), $"{model}, ball {i}: the first step is finite");
                        }

                        diverged[i] = outcome == StepOutcome.Diverged;
                        Assert.That(batch.HasDiverged(i), Is.EqualTo(diverged[i]), $"{model}, ball {i}, step {n}");
                        // The velocity on its own too (the failure this test was written for was in the velocity).
                        Assert.That(batch.GetState(i).Velocity, Is.EqualTo(steppers[i].State.Velocity), $"{model}, ball {i}, step {n}");
                        Assert.That(Difference(batch.GetState(i), steppers[i].State), Is.EqualTo(0), $"{model}, ball {i}, step {n}");
                    }
                }
            }
        }

        // DivergingBall_StopsAtItsLastFiniteState's ball: a beach ball's size at 2 g, no gravity, the given drag law.
        private static FlightModel LightBall(IDragModel drag) => new FlightModel(new Ball(0.002, 0.2, 0.67), new Air(1.21), Vector3d.Zero, drag);

        // Its start: 100 m up at 100 m/s along x (with no gravity the height stays 100 m, so no landing comes first). Steps
        // of 1 s, far beyond RK4's stability limit for it, make its speed overflow within a few steps.
        private static readonly FlightState FastStart = new FlightState(new Vector3d(0, 0, 100), new Vector3d(100, 0, 0), default);

        [Test]
        public void DivergingBall_StopsAtItsLastFiniteState()
        {
            // The light ball from its fast start with 1 s steps (LightBall, FastStart): the speed overflows within a few.
            var batch = new BallBatch(LightBall(new ConstantDrag(0.5)), 1, new Plane(Vector3d.Zero, Vector3d.UnitZ));
            batch.Add(FastStart);
            for (int i = 0; i < 20 && batch.IsFlying(0); i++)
            {
                batch.Advance(1.0);
            }

            Assert.That(batch.HasDiverged(0), Is.True);
            Assert.That(batch.GetState(0).IsFinite, Is.True);
            Assert.That(batch.TryGetLanding(0, out _), Is.False);
        }

        /// <summary>A user's own drag law (a constant C_D), which no vector lane runs: its batch goes ball by ball.</summary>
        private sealed class UserConstantDrag : IDragModel
        {
            public double DragCoefficient(in AeroConditions conditions) => 0.5;
        }

        [Test]
        public void DivergingBall_InOneCallOfManySteps_StopsWhereOneStepACallStops([Values] bool userLaw)
        {
            // DivergingBall_StopsAtItsLastFiniteState's ball, 20 steps of 1 s in one call (the overflow comes within a few):
            // the steps after the refused one are not taken, and the ball keeps its last finite state. With a user's drag
            // law the batch goes ball by ball on every runtime.
            IDragModel drag = userLaw ? new UserConstantDrag() : new ConstantDrag(0.5);
            FlightModel model = LightBall(drag);
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            var together = new BallBatch(model, 1, ground);
            var apart = new BallBatch(model, 1, ground);
            together.Add(FastStart);
            apart.Add(FastStart);

            together.Advance(1.0, 20);
            for (int i = 0; i < 20; i++)
            {
                apart.Advance(1.0);
            }

            Assert.That(together.IsVectorized, Is.EqualTo(!userLaw && Vector.IsHardwareAccelerated));
            Assert.That(together.HasDiverged(0), Is.True);
            Assert.That(together.GetState(0).IsFinite, Is.True);
            Assert.That(together.GetState(0).Time, Is.GreaterThan(0), "some steps were taken before the overflow");
            AssertSameBall(together, apart, 0, drag.ToString()!);
        }

        /// <summary>A user's constant drag law that throws from its call number ThrowAt on (0: never).</summary>
        private sealed class FailingDrag : IDragModel
        {
            public int Calls;
            public int ThrowAt;

            public double DragCoefficient(in AeroConditions conditions)
            {
                Calls++;
                if (ThrowAt > 0 && Calls >= ThrowAt)
                {
                    throw new InvalidOperationException("the user's drag law failed");
                }

                return 0.5;
            }
        }

        [Test]
        public void UserLawThatThrows_LeavesEveryBallAsItWas([Values(1, 9, 30)] int throwAt)
        {
            // Advance's documented state after a user's law throws (robustness.md: a call that throws leaves its object as it
            // was). Four balls, four steps of 1/240 s a call: ball 0 just above the ground and heading down, so that it lands
            // in the second step of the second call; balls 1 and 2 high above it; ball 3 on it and heading down, landed in
            // the first call. In the second call the law fails on its first call (ball 0's first step), on its 9th (ball 1's
            // first step, after ball 0 landed in two steps of 4 calls each) or on its 30th (inside ball 2's second step,
            // after ball 1's four steps).
            var drag = new FailingDrag();
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, drag);
            FlightState[] starts = Starts(4);
            var launches = new[]
            {
                new FlightState(new Vector3d(0, 0, 0.044), new Vector3d(10, 0, -2), default),
                Raised(starts[1]),
                Raised(starts[2]),
                starts[0],
            };
            var batch = new BallBatch(model, 5); // room for a fifth, which the last check tries to add
            var twin = new BallBatch(model, 4);
            var ahead = new BallBatch(model, 4);
            foreach (FlightState launch in launches)
            {
                batch.Add(launch);
                twin.Add(launch);
                ahead.Add(launch);
            }

            batch.Advance(1.0 / 240, 4);
            twin.Advance(1.0 / 240, 4);
            ahead.Advance(1.0 / 240, 4);
            Assert.That(batch.IsFlying(0) && !batch.IsFlying(3), Is.True, "after the first call ball 0 flies and ball 3 landed");
            drag.Calls = 0;
            ahead.Advance(1.0 / 240, 4);
            Assert.That(ahead.TryGetLanding(0, out FlightState aheadLanding), Is.True, "ball 0 lands in the second call");
            Assert.That(aheadLanding.Time, Is.GreaterThan(5.0 / 240).And.LessThanOrEqualTo(6.0 / 240), "in its second step");
            Assert.That(drag.Calls, Is.EqualTo(8 + 16 + 16), "two steps for ball 0, four for balls 1 and 2");

            var before = new FlightState[4];
            for (int i = 0; i < 4; i++)
            {
                before[i] = batch.GetState(i);
            }

            drag.Calls = 0;
            drag.ThrowAt = throwAt;
            var failed = Assert.Throws<InvalidOperationException>(() => batch.Advance(1.0 / 240, 4));
            Assert.That(failed!.Message, Does.Contain("drag law failed"));
            Assert.That(drag.Calls, Is.EqualTo(throwAt), "the law was called up to its failing call");
            for (int i = 0; i < 4; i++)
            {
                Assert.That(batch.GetState(i), Is.EqualTo(before[i]), $"ball {i} as it was");
                AssertSameBall(batch, twin, i, $"ball {i} as its twin, which did not take the failed call");
            }

            Assert.That(batch.IsFlying(0) && !batch.TryGetLanding(0, out _) && !batch.HasDiverged(0), Is.True, "ball 0 flies again, as before the call");

            // Once the law behaves, the next call is the call the twin makes, and the one the batch ahead made.
            drag.ThrowAt = 0;
            batch.Advance(1.0 / 240, 4);
            twin.Advance(1.0 / 240, 4);
            for (int i = 0; i < 4; i++)
            {
                AssertSameBall(batch, twin, i, $"ball {i} after the next call");
                AssertSameBall(batch, ahead, i, $"ball {i} after the next call, as the batch ahead");
            }

            // And a ball added while the law throws is not added.
            drag.ThrowAt = drag.Calls + 1;
            var thrown = Assert.Throws<InvalidOperationException>(() => batch.Add(starts[1]));
            Assert.That(thrown!.Message, Does.Contain("drag law failed"));
            Assert.That(batch.Count, Is.EqualTo(4));
            Assert.That(batch.IsVectorized, Is.False);

            static FlightState Raised(in FlightState start) =>
                new FlightState(start.Position + new Vector3d(0, 0, 100), start.Velocity, start.AngularVelocity, start.Time);
        }

        [Test]
        public void UserLawThatThrows_AfterABallDivergedInTheCall_LeavesItFlyingAsItWas()
        {
            // DivergingBall_StopsAtItsLastFiniteState's light ball with a user's drag law and no gravity, steps of 1 s. Ball 0
            // at 100 m/s overflows within a few steps; ball 1 at 1 cm/s stays stable (h k |v| = 0.2). The law fails on ball 1's
            // first call, after ball 0 diverged in the same call: ball 0 must fly again, at its state before the call.
            var drag = new FailingDrag();
            FlightModel model = LightBall(drag);
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            FlightState fast = FastStart;
            var slow = new FlightState(new Vector3d(0, 0, 100), new Vector3d(0.01, 0, 0), default);

            // How many calls ball 0's steps take until it diverges, from a batch of ball 0 alone.
            var alone = new BallBatch(model, 1, ground);
            alone.Add(fast);
            drag.Calls = 0;
            alone.Advance(1.0, 20);
            Assert.That(alone.HasDiverged(0), Is.True, "ball 0 diverges within 20 steps");
            int ballZeroCalls = drag.Calls;

            var batch = new BallBatch(model, 2, ground);
            batch.Add(fast);
            batch.Add(slow);
            drag.Calls = 0;
            drag.ThrowAt = ballZeroCalls + 1;
            Assert.Throws<InvalidOperationException>(() => batch.Advance(1.0, 20));
            for (int i = 0; i < 2; i++)
            {
                Assert.That(batch.GetState(i), Is.EqualTo(i == 0 ? fast : slow), $"ball {i} as it was");
                Assert.That(batch.IsFlying(i) && !batch.HasDiverged(i) && !batch.TryGetLanding(i, out _), Is.True, $"ball {i} flies");
            }

            drag.ThrowAt = 0;
            batch.Advance(1.0, 20);
            Assert.That(batch.HasDiverged(0), Is.True, "and diverges again once the law behaves");
            Assert.That(Difference(batch.GetState(0), alone.GetState(0)), Is.EqualTo(0), "at the same last finite state");
        }

        // Ball i in two batches: the same state bit for bit, and the same flying, landing and divergence.
        private static void AssertSameBall(BallBatch a, BallBatch b, int i, string what)
        {
            Assert.That(Difference(a.GetState(i), b.GetState(i)), Is.EqualTo(0), $"{what}, ball {i}");
            Assert.That(a.GetState(i).Velocity, Is.EqualTo(b.GetState(i).Velocity), $"{what}, ball {i}");
            Assert.That(a.IsFlying(i), Is.EqualTo(b.IsFlying(i)), $"{what}, ball {i}");
            Assert.That(a.HasDiverged(i), Is.EqualTo(b.HasDiverged(i)), $"{what}, ball {i}");
            Assert.That(a.TryGetLanding(i, out FlightState landingA), Is.EqualTo(b.TryGetLanding(i, out FlightState landingB)), $"{what}, ball {i}");
            Assert.That(Difference(landingA, landingB), Is.EqualTo(0), $"{what}, ball {i}");
        }

        // A batch of these starts over this ground and, for each, a stepper flying the same ball by RK4 (the single-ball path).
        private static (BallBatch Batch, FlightStepper[] Steppers) BatchAndSteppers(FlightModel model, Plane ground, FlightState[] starts)
        {
            var batch = new BallBatch(model, starts.Length, ground);
            var steppers = new FlightStepper[starts.Length];
            for (int i = 0; i < starts.Length; i++)
            {
                batch.Add(starts[i]);
                steppers[i] = new FlightStepper(model, RungeKutta4.Instance, new FlightEventSet(Vector3d.Zero, ground));
                steppers[i].Reset(starts[i]);
            }

            return (batch, steppers);
        }

        // The batch and its single-ball steppers advanced together, count steps of step: every stepper's step is taken, and
        // every ball's state is the stepper's, bit for bit, after each step.
        private static void AssertFlyAlike(BallBatch batch, FlightStepper[] steppers, double step, int count, string what)
        {
            for (int n = 0; n < count; n++)
            {
                batch.Advance(step);
                for (int i = 0; i < steppers.Length; i++)
                {
                    Assert.That(steppers[i].TryStep(step, FlightEventKinds.Landing), Is.EqualTo(StepOutcome.Taken), $"{what}, ball {i}, step {n}");
                    Assert.That(Difference(batch.GetState(i), steppers[i].State), Is.EqualTo(0), $"{what}, ball {i}, step {n}");
                }
            }
        }

        // The largest difference of position, velocity, spin and time, each relative to its own size (at least 1): a
        // velocity is not let off by the size of a fast spin.
        private static double Difference(in FlightState a, in FlightState b)
        {
            static double Relative(in Vector3d x, in Vector3d y) => (x - y).Length / Math.Max(1, y.Length);
            return Math.Max(
                Math.Max(Relative(a.Position, b.Position), Relative(a.Velocity, b.Velocity)),
                Math.Max(Relative(a.AngularVelocity, b.AngularVelocity), Math.Abs(a.Time - b.Time) / Math.Max(1, Math.Abs(b.Time))));
        }
    }
}
