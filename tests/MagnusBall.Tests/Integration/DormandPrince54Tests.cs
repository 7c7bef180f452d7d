using MagnusBall.Flight;
using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Tests.Integration
{
    /// <summary>The Dormand-Prince 5(4) pair: order, error control, dense output, FSAL, no allocation, bad input.</summary>
    [TestFixture]
    public class DormandPrince54Tests
    {
        private static FlightModel Model() =>
            new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));

        private static FlightState Start()
        {
            Vector3d velocity = new Vector3d(30 * Math.Cos(0.15), 0, 30 * Math.Sin(0.15));
            return new FlightState(new Vector3d(0, 0, 1), velocity, Spin.Topspin(velocity, Vector3d.UnitZ, Spin.FromRevolutionsPerSecond(30)));
        }

        private static FlightState Reference(double time)
        {
            int steps = (int)Math.Round(time / 1e-5);
            return Shots.Fly(Model(), RungeKutta4.Instance, Start(), time / steps, steps);
        }

        private static double Distance(in FlightState a, in FlightState b) =>
            Math.Sqrt((a.Position - b.Position).LengthSquared + (a.Velocity - b.Velocity).LengthSquared + (a.AngularVelocity - b.AngularVelocity).LengthSquared);

        [Test]
        public void Interpolation_IsTheVectorForm()
        {
            // The dense output's interpolation is written component by component, and must be the Vector3d form, the same bits
            // (the cross-runtime check relies on it). Random steps on four models, with components of +-0, subnormal, ordinary
            // and up to 1e150, and steps from 1e-300 to 10 s, at six fractions; a one-operation reordering fails this.
            var random = new Random(20261202);
            FlightModel[] models =
            {
                FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp),
                new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(2, -1, 0)), Gravity.YUp, StepanekDrag.Instance, StepanekLift.Instance,
                    new ExponentialSpinDecay(20)),
                new FlightModel(Ball.Soccer, new Air(1.2).WithLogarithmicWind(new Vector3d(5, 0, 0)), Gravity.ZUp, GoffCarreSoccerDrag.Instance,
                    PiecewiseLinearLift.SoccerGoffCarre),
                FlightModel.Vacuum(Ball.Tennis, new Vector3d(0, -9.81, 0)),
            };
            double Component()
            {
                switch (random.Next(6))
                {
                    case 0: return random.Next(2) == 0 ? 0.0 : -0.0;
                    case 1: return (random.Next(2) == 0 ? 1 : -1) * 1e-310 * random.NextDouble();
                    case 2: return (random.NextDouble() * 2 - 1) * Math.Pow(10, 150 * random.NextDouble());
                    default: return (random.NextDouble() * 2 - 1) * 50;
                }
            }

            Vector3d Vector() => new Vector3d(Component(), Component(), Component());
            int checkedSteps = 0;
            for (int n = 0; n < 4000; n++)
            {
                FlightModel model = models[n % models.Length];
                var state = new FlightState(Vector(), Vector(), Vector(), random.NextDouble());
                StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                double h = Math.Pow(10, 301 * random.NextDouble() - 300);
                if (!k1.IsFinite)
                {
                    continue;
                }

                DormandPrince54.Instance.TryStep(model, state, k1, h, out DormandPrince54Step step);
                foreach (double theta in new[] { 0.0, 0.125, 0.37, 0.5, 0.9, 1.0 })
                {
                    Assert.That(step.InterpolationAlikeInBothForms(theta), Is.True, $"theta {theta}: {model}, {state}, h {h:R}");
                }

                checkedSteps++;
            }

            Assert.That(checkedSteps, Is.GreaterThan(3000));
        }

        [Test]
        public void FixedStep_ConvergesAtFifthOrder()
        {
            FlightState reference = Reference(1.0);
            // 10-40 steps per second: the asymptotic range (at 5 steps the ratio is still pre-asymptotic, ~6.3),
            // and the 40-step error (~7e-10) stays far above the reference's own (~1e-12).
            int[] counts = { 10, 20, 40 };
            double[] errors = new double[counts.Length];
            for (int i = 0; i < counts.Length; i++)
            {
                errors[i] = Distance(Shots.Fly(Model(), DormandPrince54.Instance, Start(), 1.0 / counts[i], counts[i]), reference);
            }

            double slope = Math.Log(errors[0] / errors[counts.Length - 1]) / Math.Log(counts[counts.Length - 1] / (double)counts[0]);
            TestContext.Out.WriteLine($"dp54 fixed-step order {slope:F3}; errors {string.Join(", ", errors)}");
            // 0.15: the same bound the core's convergence tests give the other methods.
            Assert.That(slope, Is.EqualTo(5).Within(0.15));
        }

        [Test]
        public void Adaptive_AtTightTolerance_MatchesRk4AtTenMicroseconds()
        {
            var method = new DormandPrince54(1e-12, 1e-12);
            FlightState end = AdaptiveFlight.Fly(method, Model(), Start(), 1.0, out long evaluations);
            FlightState reference = Reference(1.0);
            TestContext.Out.WriteLine($"dp54 @1e-12: {evaluations} evaluations, distance to RK4@1e-5 s {Distance(end, reference):E3}");
            // 1e-9: RK4 at 1e-5 s is accurate to ~1e-13 here (error ~ C h^4), DP54 at 1e-12 to ~1e-11; 1e-9
            // leaves room for the accumulated rounding of the 100,000 RK4 steps (~1e5 * 1e-16 * 30 m/s).
            Assert.That(Distance(end, reference), Is.LessThan(1e-9));
            Assert.That(end.Time, Is.EqualTo(1.0));
            Assert.That(evaluations, Is.LessThan(100_000), "it must be far cheaper than the fixed-step reference");
        }

        [Test]
        public void Adaptive_ErrorFollowsTheTolerance()
        {
            FlightState reference = Reference(1.0);
            double previous = double.PositiveInfinity;
            foreach (double tolerance in new[] { 1e-4, 1e-6, 1e-8, 1e-10 })
            {
                var method = new DormandPrince54(tolerance, tolerance);
                FlightState end = AdaptiveFlight.Fly(method, Model(), Start(), 1.0, out long evaluations);
                double error = Distance(end, reference);
                TestContext.Out.WriteLine($"tol {tolerance:E0}: error {error:E3} with {evaluations} evaluations");
                // Each hundredfold tighter tolerance must buy at least a tenfold smaller error (the controller
                // keeps the local error near tol; the global error follows it within a modest factor).
                Assert.That(error, Is.LessThan(previous / 10));
                // 1000 tol: the global error of a 1 s flight with ~tol local error per unit-scaled component.
                Assert.That(error, Is.LessThan(1000 * tolerance));
                previous = error;
            }
        }

        [Test]
        public void TryStep_RetriedFromTheResultsOwnStart_StepsFromThatStart()
        {
            // The retry after a rejection, written the natural way: the start and its derivative read from the rejected
            // step itself, the result written over it. Start and StartDerivative are fields of the step (it is filled in
            // place), so the call must read them before it overwrites the step.
            FlightModel model = Model();
            FlightState start = Start();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
            var method = new DormandPrince54(1e-9, 1e-12);
            Assert.That(method.TryStep(model, start, k1, 0.5, out DormandPrince54Step step), Is.False, "0.5 s at these tolerances is rejected");
            double retry = step.NextStep;
            bool fresh = method.TryStep(model, start, k1, retry, out DormandPrince54Step expected);
            bool reused = method.TryStep(model, step.Start, step.StartDerivative, retry, out step);
            Assert.That(reused, Is.EqualTo(fresh));
            Assert.That(step.Start, Is.EqualTo(start));
            Assert.That(step.End, Is.EqualTo(expected.End), "the same step as from a copy of the start, bit for bit");
            Assert.That(step.ErrorNorm, Is.EqualTo(expected.ErrorNorm));

            Assert.That(method.TryStepThroughDerivative(model, start, k1, 0.5, out DormandPrince54Step through), Is.False);
            method.TryStepThroughDerivative(model, through.Start, through.StartDerivative, retry, out through);
            Assert.That(through.Start, Is.EqualTo(start));
            Assert.That(through.End, Is.EqualTo(expected.End));
        }

        [Test]
        public void TryStep_IsFsalAndItsDenseOutputMatchesTheEnds()
        {
            FlightModel model = Model();
            FlightState start = Start();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
            bool accepted = DormandPrince54.Instance.TryStep(model, start, k1, 1e-3, out DormandPrince54Step step);

            Assert.That(accepted, Is.True);
            StateDerivative k7 = FlightKernel.DerivativeOf(model, step.End);
            Assert.That(step.EndDerivative.Acceleration, Is.EqualTo(k7.Acceleration), "k7 = f(y1) is handed back as the next k1");
            Assert.That(step.End.Position, Is.EqualTo(((IIntegrator)DormandPrince54.Instance).Step(model, start, k1, 1e-3).Position), "TryStep and Step agree");
            Assert.That(step.InterpolateFraction(0).Position, Is.EqualTo(start.Position));
            // 1e-15 m: rounding of y0 + (y1 - y0) at positions of order 1 m.
            Assert.That(Vector3d.Distance(step.InterpolateFraction(1).Position, step.End.Position), Is.LessThan(1e-15));
            Assert.That(step.Interpolate(step.Start.Time + 0.5e-3).Time, Is.EqualTo(start.Time + 0.5e-3).Within(1e-18));
        }

        [Test]
        public void DenseOutput_LocalErrorFallsAsStepToTheFifth()
        {
            // The continuous extension is fourth order: its error inside one step falls as h^5.
            FlightModel model = Model();
            FlightState start = Start();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
            double[] steps = { 0.2, 0.1, 0.05 };
            double[] errors = new double[steps.Length];
            for (int i = 0; i < steps.Length; i++)
            {
                var method = new DormandPrince54(1, 1);
                method.TryStep(model, start, k1, steps[i], out DormandPrince54Step step);
                FlightState inside = step.InterpolateFraction(0.37);
                FlightState exact = Shots.Fly(model, RungeKutta4.Instance, start, 0.37 * steps[i] / 2000, 2000);
                errors[i] = Distance(inside, exact);
            }

            double slope = Math.Log(errors[0] / errors[2]) / Math.Log(4);
            TestContext.Out.WriteLine($"dense-output local order {slope:F3}; errors {string.Join(", ", errors)}");
            // 4.5: a fourth-order interpolant has local error O(h^5); a third-order one (cubic Hermite) would give ~4.
            Assert.That(slope, Is.GreaterThan(4.5));
        }

        [Test]
        public void AdaptiveStepping_AllocatesNothing()
        {
            FlightModel model = Model();
            var method = new DormandPrince54(1e-9, 1e-9);
            // The helper's warm-up runs every call measured below, not only the flight: a runtime may allocate while it
            // compiles a method on its first call (Mono 6.8's JIT does, 64 B here), and that is not the stepping's own.
            var flight = new FlightStepper(model, RungeKutta4.Instance);
            double sum = 0;
            Action rounds = () =>
            {
                for (int i = 0; i < 200; i++)
                {
                    sum += AdaptiveRound(flight, model, method); // each round flies from Start()
                }
            };

            long allocated = Allocation.SteadyStateBytes(rounds);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(double.IsFinite(sum), Is.True);
        }

        private static double AdaptiveRound(FlightStepper flight, FlightModel model, DormandPrince54 method)
        {
            FlightState end = AdaptiveFlight.Fly(flight, method, Start(), 1.0);
            FlightState start = Start();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
            method.TryStep(model, start, k1, 0.01, out DormandPrince54Step attempt);
            return end.Position.X + attempt.InterpolateFraction(0.5).Position.X + method.Step(model, start, k1, 0.01).Position.X;
        }

        [Test]
        public void ControllerPower_IsWithinItsBoundOfTheTruePower()
        {
            // The step controller's norm^(-1/5) (sqrt of the portable x^(-2/5), scaled by powers of two) against Math.Pow, which
            // is within 1 ulp itself: 200,000 norms spread log-uniformly over the controller's unclamped range [1.8e-4, 2000],
            // 20,000 over [1e-300, 1e300], and the powers of two and their neighbours, where the scaling switches.
            // Math.Pow(x, -0.2) raises x to the double nearest -0.2, which is -0.2 - 1.11e-17: far from 1 that is up to 8e-15 off
            // the fifth root (40 ulp at 1e-300), so the reference is corrected by x^(1.11e-17) = 1 + 1.11e-17 ln x. The bound,
            // 2.6 ulp, is the function's 1.6 ulp (its doc) plus the reference's own 1 ulp (it was 2 with the function's earlier
            // 1 ulp; measured 2.00 now).
            const double exponentError = 1.1102230246251565e-17; // -0.2 minus the double nearest it
            var random = new Random(11);
            double worst = 0, worstAt = 0;
            void Check(double x)
            {
                double expected = Math.Pow(x, -0.2) * (1 + exponentError * Math.Log(x)), got = DormandPrince54.PowMinusOneFifth(x);
                double ulp = Next(expected, 1) - expected;
                double error = Math.Abs(got - expected) / ulp;
                if (error > worst)
                {
                    worst = error;
                    worstAt = x;
                }

                Assert.That(error, Is.LessThanOrEqualTo(2.6), $"x = {x:R}: {got:R} against {expected:R}");
            }

            for (int i = 0; i < 200_000; i++)
            {
                Check(1.8e-4 * Math.Pow(2000 / 1.8e-4, random.NextDouble()));
            }

            TestContext.Out.WriteLine($"controller's range: worst error {worst:F2} ulp at {worstAt:R}");
            for (int i = 0; i < 20_000; i++)
            {
                Check(Math.Pow(10, 600 * random.NextDouble() - 300));
            }

            for (int e = -996; e <= 1000; e++)
            {
                double x = Math.Pow(2, e);
                Check(x);
                Check(Next(x, 1));
                Check(Next(x, -1));
            }

            TestContext.Out.WriteLine($"everywhere: worst error {worst:F2} ulp at {worstAt:R}");
        }

        // The neighbour of a positive double by its bits (not Math.BitIncrement, which Mono 6.8's corlib lacks: the suite also
        // builds for Mono, tools/test-mono.sh).
        private static double Next(double x, int direction) => BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(x) + direction);

        [Test]
        public void StaysClearOf_NeverHidesAnEventTheSearchFinds_AndClearsMostSteps()
        {
            // The flight core skips the event search on a step the bound calls clear, so the bound must never call a step
            // clear where the search finds a crossing or an apex. Random drives and lobs flown adaptively (loose and tight
            // tolerances); against every accepted step: grounds every 0.25 m of height, walls every metre, an oblique plane,
            // both directions, and near misses: planes through the step's own interpolant mid-step and just above its top.
            FlightModel model = Model();
            var random = new Random(3);
            int checks = 0, clear = 0, found = 0;
            var planes = new System.Collections.Generic.List<Plane>();
            for (int shot = 0; shot < 30; shot++)
            {
                double elevation = -0.2 + 1.4 * random.NextDouble(), speed = 5 + 45 * random.NextDouble();
                var velocity = new Vector3d(speed * Math.Cos(elevation), 3 * (random.NextDouble() - 0.5), speed * Math.Sin(elevation));
                double rpm = 6000 * random.NextDouble() - 2000;
                Vector3d spin = rpm >= 0 ? Spin.Topspin(velocity, Vector3d.UnitZ, Spin.FromRpm(rpm)) : Spin.Backspin(velocity, Vector3d.UnitZ, Spin.FromRpm(-rpm));
                var state = new FlightState(new Vector3d(0, 0, 1), velocity, spin);
                StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                var method = shot % 2 == 0 ? new DormandPrince54(1e-5, 1e-5) : new DormandPrince54(1e-8, 1e-8);
                double h = 0.02;
                for (int i = 0; i < 400 && state.Time < 4; i++)
                {
                    if (!method.TryStep(model, state, k1, h, out DormandPrince54Step step))
                    {
                        h = step.NextStep;
                        continue;
                    }

                    planes.Clear();
                    for (double z = -2; z <= 30; z += 0.25)
                    {
                        planes.Add(new Plane(new Vector3d(0, 0, z), Vector3d.UnitZ));
                    }

                    for (double x = 0; x <= 60; x += 1)
                    {
                        planes.Add(new Plane(new Vector3d(x, 0, 0), Vector3d.UnitX));
                    }

                    planes.Add(new Plane(new Vector3d(10, 0, 2), new Vector3d(0.6, 0.1, 0.8)));
                    FlightState middle = step.InterpolateFraction(0.5);
                    planes.Add(new Plane(middle.Position, middle.Velocity.NormalizedOrZero()));
                    planes.Add(new Plane(middle.Position, Vector3d.UnitZ));
                    double top = Math.Max(step.Start.Position.Z, step.End.Position.Z);
                    for (int j = 0; j < 9; j++)
                    {
                        double z = j == 8 ? middle.Position.Z : top + Math.Pow(10, -j - 3);
                        planes.Add(new Plane(new Vector3d(0, 0, z), Vector3d.UnitZ));
                    }

                    foreach (Plane plane in planes)
                    {
                        foreach (CrossingDirection direction in new[] { CrossingDirection.AgainstNormal, CrossingDirection.AlongNormal })
                        {
                            bool crosses = step.TryFindCrossing(plane, direction, false, out _);
                            bool isClear = step.StaysClearOf(plane, direction);
                            Assert.That(isClear && crosses, Is.False, $"{plane} {direction} called clear in a step that crosses it, from {step.Start}");
                            checks++;
                            clear += isClear ? 1 : 0;
                            found += crosses ? 1 : 0;
                        }
                    }

                    bool apex = step.TryFindApex(Vector3d.UnitZ, out _);
                    Assert.That(apex && step.StaysClearOfApex(Vector3d.UnitZ), Is.False, $"apex called clear from {step.Start}");
                    found += apex ? 1 : 0;
                    state = step.End;
                    k1 = step.EndDerivative;
                    h = step.NextStep;
                }
            }

            TestContext.Out.WriteLine($"{checks} checks, {found} events found, {clear} steps called clear");
            Assert.That(found, Is.GreaterThan(1000), "the flights cross many of the planes");
            // The bound is useful: most step-plane pairs are clear (nearly every plane the step does not cross).
            Assert.That(clear, Is.GreaterThan(checks * 3 / 4));
        }

        [Test]
        public void StaysClearOf_APlaneFarBelow_IsClear_EvenWhereTheBoundsNumbersSumPastDoubleMaxValue()
        {
            // A ground 9e307 m below the ball: the distances at the step's ends (9e307 each) are finite and so is the margin
            // (1e-12 of the magnitudes, ~9e295), but their sum overflows. The bound is min(g0, g1) + ... > margin, so the
            // step is clear; a finiteness test on the sum of the bound's numbers would call it not finite and answer false.
            FlightModel model = Model();
            FlightState state = Start();
            Assert.That(new DormandPrince54(1e-6, 1e-9).TryStep(model, state, FlightKernel.DerivativeOf(model, state), 0.01, out DormandPrince54Step step), Is.True);
            var plane = new Plane(new Vector3d(0, 0, -9e307), Vector3d.UnitZ);
            Assert.That(step.TryFindCrossing(plane, CrossingDirection.AgainstNormal, false, out _), Is.False);
            Assert.That(step.StaysClearOf(plane, CrossingDirection.AgainstNormal), Is.True);
            // Mirrored: the far plane above the ball, approached from below (the bound's upper side).
            var above = new Plane(new Vector3d(0, 0, 9e307), Vector3d.UnitZ);
            Assert.That(step.StaysClearOf(above, CrossingDirection.AlongNormal), Is.True);
        }

        [Test]
        public void AdaptiveSteps_InTheCore_CountEveryRealEvaluation()
        {
            FlightModel model = Model();
            var calls = new EvaluationCount();
            model.CountedEvaluations = calls;
            var flight = new FlightStepper(model, RungeKutta4.Instance);
            AdaptiveFlight.Fly(flight, new DormandPrince54(1e-6, 1e-9), Start(), 1.0);
            Assert.That(flight.DerivativeEvaluations, Is.EqualTo(calls.Calls), "the counter counts calls of the model itself");
            Assert.That(calls.Calls, Is.GreaterThan(7));
        }

        [Test]
        public void BadInput_ThrowsArgumentExceptionNamingTheParameter()
        {
            FlightModel model = Model();
            FlightState start = Start();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
            var nanState = new FlightState(new Vector3d(double.NaN, 0, 0), start.Velocity, start.AngularVelocity);

            Assert.That(() => new DormandPrince54(0, 1e-9), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("relativeTolerance"));
            Assert.That(() => new DormandPrince54(double.NaN, 1e-9), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("relativeTolerance"));
            Assert.That(() => new DormandPrince54(1e-6, -1), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("absoluteTolerance"));
            Assert.That(() => ((IIntegrator)DormandPrince54.Instance).Step(model, start, k1, 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("step"));
            Assert.That(() => ((IIntegrator)DormandPrince54.Instance).Step(model, start, k1, double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("step"));
            Assert.That(() => DormandPrince54.Instance.TryStep(model, nanState, k1, 0.01, out _), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("state"));
            Assert.That(() => DormandPrince54.Instance.TryStep(null!, start, k1, 0.01, out _), Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("model"));
            var flight = new FlightStepper(model, RungeKutta4.Instance);
            flight.Reset(start);
            Assert.That(() => flight.TryStepAdaptive(DormandPrince54.Instance, -1), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("maxStep"));
            Assert.That(() => flight.TryStepAdaptive(DormandPrince54.Instance, double.PositiveInfinity), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("maxStep"));
            Assert.That(() => flight.TryStepAdaptive(null!, 1), Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("method"));
            Assert.That(() => DormandPrince54.Instance.InitialStep(model, start, k1, -1), Throws.InstanceOf<ArgumentOutOfRangeException>());
            DormandPrince54.Instance.TryStep(model, start, k1, 0.01, out DormandPrince54Step ok);
            Assert.That(() => ok.Interpolate(double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("time"));
        }
    
        [Test]
        public void StepAskedFor_IsTakenFromTheSameStart_AndSkipsTheControllersRamp()
        {
            // The aim solver starts its later trials with the step the first trial's controller asked for at the launch. That
            // step must be one the method accepts from the same start (norm <= 1), and worth asking for: more than five times
            // InitialStep's guess (the controller grows a step at most fivefold, so a trial started with it skips at least
            // one step of that ramp; measured 9-10 times). Were the local error to grow as h^5 all the way, its norm would be
            // 0.9^5 = 0.59; it grows more slowly over the tenfold step (measured 0.14-0.35), so the bound 0.05 says only that
            // the step is within (0.59 / 0.05)^(1/5) = 1.6 times of the one the h^5 law picks. The full tennis model, both of
            // the aim solver's tolerances and three launches.
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            foreach (double tolerance in new[] { 1e-5, 1e-8 })
            {
                var method = new DormandPrince54(tolerance, tolerance);
                foreach (double elevation in new[] { -0.7, 0.1, 0.9 })
                {
                    var velocity = new Vector3d(30 * Math.Cos(elevation), 0, 30 * Math.Sin(elevation));
                    var start = new FlightState(new Vector3d(0, 0, 1), velocity, Spin.Topspin(velocity, Vector3d.UnitZ, Spin.FromRevolutionsPerSecond(20)));
                    StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
                    double first = method.InitialStep(model, start, k1, 0.5);
                    Assert.That(method.TryStep(model, start, k1, first, out DormandPrince54Step step), Is.True);
                    double asked = DormandPrince54.StepAskedFor(step);
                    Assert.That(asked, Is.GreaterThan(5 * first), "more than the controller's fivefold growth");
                    Assert.That(method.TryStep(model, start, k1, asked, out DormandPrince54Step again), Is.True, $"tolerance {tolerance}, elevation {elevation}");
                    TestContext.Out.WriteLine($"tolerance {tolerance:E0}, elevation {elevation}: first {first:E3} s, asked {asked:E3} s, norm there {again.ErrorNorm:F3}");
                    Assert.That(again.ErrorNorm, Is.GreaterThan(0.05), "not far below the tolerance");
                }
            }
        }

        [Test]
        public void StepAskedFor_OfARejectedStep_IsNaN()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 0, 3), new Vector3d(0, 120, 0));
            var method = new DormandPrince54(1e-8, 1e-8);
            Assert.That(method.TryStep(model, start, FlightKernel.DerivativeOf(model, start), 0.5, out DormandPrince54Step rejected), Is.False);
            Assert.That(DormandPrince54.StepAskedFor(rejected), Is.NaN);
        }

        [Test]
        public void Adaptive_InARotatedFrame_AgreesToItsTolerance_TheFixedStepToRounding()
        {
            // The adaptive error norm is per component (as DOPRI5's), so a rotated frame takes other steps: the results
            // agree to the tolerance, not to rounding (docs/integrators.md). One soccer kick (sidespin about a tilted
            // axis), 1.5 s, flown in z-up and in a frame turned 37 deg about (1, 2, 3).
            Vector3d axis = new Vector3d(1, 2, 3).NormalizedOrZero();
            double angle = 37 * Math.PI / 180;
            Vector3d Turn(Vector3d v) => // Rodrigues
                v * Math.Cos(angle) + Vector3d.Cross(axis, v) * Math.Sin(angle) + axis * (Vector3d.Dot(axis, v) * (1 - Math.Cos(angle)));
            var start = new FlightState(new Vector3d(0.5, -0.3, 0.11), new Vector3d(25, 2, 6), new Vector3d(30, -150, 40));
            var turnedStart = new FlightState(Turn(start.Position), Turn(start.Velocity), Turn(start.AngularVelocity));
            FlightModel zUp = MagnusBall.Presets.SportPresets.Soccer.CreateModel(Air.SeaLevel, Gravity.ZUp);
            FlightModel turned = MagnusBall.Presets.SportPresets.Soccer.CreateModel(Air.SeaLevel, Turn(Gravity.ZUp));

            FlightState a = AdaptiveFlight.Fly(DormandPrince54.Instance, zUp, start, 1.5, out long evaluationsA);
            FlightState b = AdaptiveFlight.Fly(DormandPrince54.Instance, turned, turnedStart, 1.5, out long evaluationsB);
            double adaptive = (Turn(a.Position) - b.Position).Length / a.Position.Length;

            FlightState c = start, d = turnedStart;
            for (int k = 0; k < 360; k++)
            {
                c = ((IIntegrator)RungeKutta4.Instance).Step(zUp, c, 1.0 / 240);
                d = ((IIntegrator)RungeKutta4.Instance).Step(turned, d, 1.0 / 240);
            }

            double fixedStep = (Turn(c.Position) - d.Position).Length / c.Position.Length;
            long steps = Math.Max(evaluationsA, evaluationsB) / 6; // six evaluations per accepted step (FSAL), a few retries
            TestContext.Out.WriteLine(
                $"rotated frame, relative difference of the end position: adaptive {adaptive:E2} ({steps} steps at most), fixed-step RK4 {fixedStep:E2}");
            // Fixed step: the same operations on rotated numbers, so rounding only (a few ulp per step over 360 steps).
            Assert.That(fixedStep, Is.LessThan(1e-13));
            // Adaptive: each accepted step's error is held to about rtol (1e-6) of the state, so each run is within steps x
            // rtol of the true flight, and the two runs within twice that.
            Assert.That(adaptive, Is.LessThan(2 * steps * 1e-6));
            Assert.That(adaptive, Is.GreaterThan(1e-12), "not equal to rounding: if this fails, the norm became rotation-invariant; update docs/integrators.md");
        }
}
}
