using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Batch;
using MagnusBall.Contact;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using NUnit.Framework;

namespace MagnusBall.Tests.Fuzz
{
    /// <summary>
    /// The defects the stateful fuzz (StatefulFuzz) found, one reproduction each (every one failed on the code before
    /// its fix): calls that ran unbounded, threw from inside a step and left the object changed, or left NaN behind.
    /// </summary>
    [TestFixture]
    public class StatefulFuzzFindingsTests
    {
        private static FlightModel Tennis => SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.ZUp);

        [Test]
        public void Driver_WithATinyFixedStep_StopsAtTheWorkCap_InsteadOfRunningForMinutes()
        {
            // Fixed step 1e-9 s: the default step cap is ceil(0.25 / 1e-9) + 1 = 250,000,001 steps per clamped frame
            // (minutes of work in one Advance). The work cap stops the call and drops the rest of the frame time.
            FlightModel model = Tennis;
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 5), Vector3d.Zero);
            var driver = new FixedStepDriver(model, RungeKutta4.Instance, 1e-9, start);
            AdvanceResult r = driver.Advance(0.25);
            long work = driver.DerivativeEvaluations + driver.TotalSteps;
            Assert.That(work, Is.GreaterThanOrEqualTo(FixedStepDriver.MaxEvaluationsPerAdvance));
            // One RK4 step (4 evaluations and the step itself) past the cap at most.
            Assert.That(work, Is.LessThanOrEqualTo(FixedStepDriver.MaxEvaluationsPerAdvance + 1 + 5));
            Assert.That(r.StepsTaken, Is.EqualTo(driver.TotalSteps));
            Assert.That(r.DroppedSeconds, Is.GreaterThan(0.2), "the frame time not simulated is reported");
            Assert.That(driver.Accumulator, Is.LessThan(driver.FixedStep));
        }

        [Test]
        public void Predictor_WithAHugeDuration_StopsAtTheWorkCap()
        {
            // No gravity, so nothing lands: maxDuration 1e300 s at 1/240 s used to loop for ever.
            FlightModel model = Tennis.WithGravity(Vector3d.Zero);
            var predictor = new TrajectoryPredictor(model, ExplicitEuler.Instance, 1.0 / 240, new FlightEventSet(Vector3d.UnitZ));
            var start = new FlightState(Vector3d.Zero, new Vector3d(10, 0, 0), Vector3d.Zero);
            Prediction p = predictor.Predict(start, 1e300, Span<Vector3d>.Empty);
            Assert.That(p.WorkLimitReached, Is.True);
            Assert.That(p.Stopped || p.Diverged || p.TimeCannotAdvance, Is.False);
            // Euler: one evaluation and one step a step, after the start's evaluation; so the cap is passed by one at most.
            Assert.That(p.DerivativeEvaluations + p.Steps, Is.InRange(TrajectoryPredictor.MaxEvaluationsPerPrediction, TrajectoryPredictor.MaxEvaluationsPerPrediction + 1));
            Assert.That(p.EndState.IsFinite, Is.True);
        }

        [Test]
        public void Predictor_WhoseDurationCannotAdvanceTheStartTime_SaysSo_InsteadOfThrowing()
        {
            // start 1e143 s, maxDuration 5e-324 s: endTime == start time, so the last step was 0 and TryStep threw
            // "step must be > 0; got 0" after the buffer had been written.
            var predictor = new TrajectoryPredictor(Tennis, RungeKutta4.Instance, 1.0 / 240);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(20, 0, 5), Vector3d.Zero, 1.21e143);
            Prediction p = predictor.Predict(start, double.Epsilon, Span<Vector3d>.Empty);
            Assert.That(p.TimeCannotAdvance, Is.True);
            Assert.That(p.EndState, Is.EqualTo(start));
        }

        [Test]
        public void Aim_WithAHugeTrialTime_StopsAtTheWorkCap()
        {
            // maximumFlightTime 1e300 s and a launch from 1e12 m up toward a target 1 km away, which drag keeps it from
            // reaching: each trial falls at the terminal speed for about 5e10 s (1e13 steps); the solve never returned.
            var aim = new AimSolver(Tennis, SemiImplicitEuler.Instance, 1.0 / 240, Plane.Ground(Tennis), maximumFlightTime: 1e300);
            AimSolution s = aim.ElevationToReach(new Vector3d(0, 0, 1e12), 30, default, new Vector3d(1000, 0, 0));
            Assert.That(s.Status, Is.EqualTo(AimStatus.WorkLimitReached));
            Assert.That(s.IsSolved, Is.False);
        }

        [Test]
        public void Stepper_RollThatOverflows_IsRefused_AndChangesNothing()
        {
            // Air of 1e300 kg/m^3: a ball rolling at 1 m/s decelerates at 1e298 m/s^2 (finite), so the reset is accepted, but
            // the roll's predicted speed of 4e295 m/s overflows the drag. The step threw ArgumentException from inside (the
            // Hermite of the roll) and left the stepper half-stepped; now it is refused as a divergence.
            // On a slope without rolling resistance, so the ball cannot come to rest inside the step.
            FlightModel model = SportPresets.Soccer.CreateModel(new Air(1e300), Gravity.ZUp);
            Vector3d normal = new Vector3d(0.5, 0, 1).NormalizedOrZero(), downhill = new Vector3d(1, 0, -0.5).NormalizedOrZero();
            var contact = new GroundContact(CrossBounce.Hard, new Plane(Vector3d.Zero, normal), rollingResistance: 0);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, contact);
            stepper.Reset(new FlightState(normal * model.Ball.Radius, downhill, Vector3d.Zero));
            Assert.That(stepper.Phase, Is.EqualTo(FlightPhase.Rolling));
            FlightState before = stepper.State;
            StateDerivative derivative = stepper.Derivative;
            long evaluations = stepper.DerivativeEvaluations;

            StepOutcome outcome = stepper.TryStep(1.0 / 240);
            Assert.That(outcome, Is.EqualTo(StepOutcome.Diverged));
            Assert.That(stepper.State, Is.EqualTo(before));
            Assert.That(stepper.Derivative.Acceleration, Is.EqualTo(derivative.Acceleration));
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(evaluations));
            Assert.That(stepper.StepCount, Is.Zero);
            Assert.That(stepper.Phase, Is.EqualTo(FlightPhase.Rolling));
        }

        [Test]
        public void Driver_WhoseDenseOutputOverflowsAtAnEvent_RefusesTheStep_InsteadOfThrowing()
        {
            // From the stateful fuzz (seed 15): a ball at y = 1.8e308 m whose step's cubic Hermite overflows at the apex
            // inside it. Cutting the step at the event threw ArgumentException ("endDerivative must have finite ...") from
            // inside Advance, after the accumulator had changed.
            SportPreset golf = null!;
            foreach (SportPreset p in SportPresets.All)
            {
                if (p.Drag is GolfSpinReynoldsDrag && p.Ball.Mass == 0.04593 && p.Ball.Radius == 0.021335)
                {
                    golf = p;
                }
            }

            Assert.That(golf, Is.Not.Null);
            FlightModel model = golf.CreateModel(new Air(0, new Vector3d(0, 4.9774135023774194E+269, -3.9118532669986097E+198)), Gravity.ZUp);
            var start = new FlightState(
                new Vector3d(-0.0, 1.7976931348623157E+308, 5E-324),
                new Vector3d(-3.3255943605219184E+198, 63524072356754.03, -1.167117268247713E-107),
                new Vector3d(-0.0, 1.5913362432127908E+49, -5.033950095892513E+300));
            var driver = new FixedStepDriver(model, RungeKutta4.Instance, 2.1360412232872894E-146, start);
            AdvanceResult r = default;
            Assert.DoesNotThrow(() => r = driver.Advance(0.019795278841534297));
            Assert.That(driver.State.IsFinite, Is.True);
            TestContext.Out.WriteLine($"{r}; state {driver.State}");
        }

        [Test]
        public void GolfLift_AtAnOverflowingSpinParameter_IsFinite_NotNaN()
        {
            // From the stateful fuzz (seed 2026): the golf preset at |w| = 1.8e308 rad/s and a speed of 1e-109 m/s: the spin
            // parameter |w| r / s overflows to +infinity, the saturating lift of the time gave inf / inf = NaN, and the
            // model's acceleration was NaN. The power-law lift that replaced it is taken at the largest finite S there.
            FlightModel model = null!;
            GolfSpinReynoldsLift lift = null!;
            foreach (SportPreset p in SportPresets.All)
            {
                if (p.Lift is GolfSpinReynoldsLift golf)
                {
                    lift = golf;
                    model = p.CreateModel(new Air(6.240362714510825), Vector3d.Zero);
                }
            }

            Assert.That(lift, Is.Not.Null);
            double atInfinity = lift.Evaluate(double.PositiveInfinity, 2e5);
            Assert.That(atInfinity, Is.EqualTo(lift.Evaluate(double.MaxValue, 2e5)), "the law at the largest finite S");
            Assert.That(double.IsFinite(atInfinity), Is.True);

            var state = new FlightState(
                new Vector3d(3.997233631240321E+282, 5.35699559137975E-259, 1.451156793303762E+243),
                new Vector3d(-2.241030004338823E-110, 7.711936117884922E-109, 2.5149674322293E-120),
                new Vector3d(-1.1588574467734387, 1.7976931348623157E+308, 2.3865263664784297E+36),
                4.8182166465760504E-141);
            Vector3d a = model.Derivative(state).Acceleration;
            Assert.That(double.IsNaN(a.X) || double.IsNaN(a.Y) || double.IsNaN(a.Z), Is.False, a.ToString());
        }

        [Test]
        public void GolfDrag_WithoutSpinSlope_AtAnInfiniteSpinParameter_IsItsFiniteValue_NotNaN()
        {
            // From a review's probe: a slope b of 0 (allowed: >= 0) and S = +infinity (AeroConditions at a speed of
            // 1e-300 m/s and 1e300 rad/s) made b S = 0 x infinity = NaN. A zero slope adds nothing at any S, as
            // LinearSpinDrag's a + b S already did.
            var law = new GolfSpinReynoldsDrag(0.2, 0, 0.04, 1e5, 1e4);
            var conditions = new AeroConditions(1e-300, 1e300, 1e300, 0.02, 1.2, 1.8e-5);
            Assert.That(conditions.SpinParameter, Is.EqualTo(double.PositiveInfinity));
            Assert.That(law.DragCoefficient(conditions), Is.EqualTo(law.Evaluate(0, conditions.ReynoldsNumber)));
            Assert.That(law.Evaluate(double.PositiveInfinity, 2e5), Is.EqualTo(law.Evaluate(0, 2e5)));
            // With a slope, S = +infinity stays +infinity (the model's scaled path forms the finite drag; test above).
            Assert.That(GolfSpinReynoldsDrag.BearmanHarvey.Evaluate(double.PositiveInfinity, 2e5), Is.EqualTo(double.PositiveInfinity));
        }

        [Test]
        public void SpinLinearDrag_AtAnOverflowingSpinParameter_IsTheFiniteTrueDrag()
        {
            // From the stateful fuzz: the golf preset at |w| = 1.8e308 rad/s and a speed of 1e-109 m/s. C_D = a + b S has
            // S = r|w|/s = +infinity, so k s^2 C_D was infinite; the true drag k s^2 b r|w|/s = k s b r |w| is finite and
            // tiny (about 1e195 m/s^2 here, against the spin's 1e308). The model's scaled path now forms it that way.
            foreach (SportPreset preset in new[] { SportPresets.Golf, SportPresets.GolfLinear2023 })
            {
                FlightModel model = preset.CreateModel(Air.SeaLevel, Gravity.ZUp);
                var state = new FlightState(
                    new Vector3d(0, 0, 1), new Vector3d(1e-109, 0, 0), new Vector3d(0, 1.7976931348623157E+308, 0));
                Vector3d a = model.Derivative(state).Acceleration;
                Assert.That(a.IsFinite, Is.True, $"{preset.Name}: {a}");
                // The drag term alone: k s b r |w|, along -x (the lift, along w x v, has no x part).
                double k = model.AerodynamicFactor, s = 1e-109, w = 1.7976931348623157E+308, r = model.Ball.Radius;
                double slope = preset.Drag is GolfSpinReynoldsDrag golf ? golf.SpinSlope : ((LinearSpinDrag)preset.Drag!).Slope;
                double expected = k * s * (slope * r) * w;
                Assert.That(-a.X, Is.EqualTo(expected).Within(1e-9 * expected), preset.Name);
            }
        }

        [Test]
        public void StateAt_BetweenFiniteEndsNearTheLargestDouble_IsFinite()
        {
            // From the stateful fuzz: a step whose ends are finite but near 1e308; the cubic Hermite's terms overflowed
            // between them. At mid-step the true value is 1.7e308 + (1e308 - 1e308)/8 = 1.7e308.
            var start = new FlightState(new Vector3d(1.7e308, 0, 0), new Vector3d(1e308, 0, 0), Vector3d.Zero, 0);
            var end = new FlightState(new Vector3d(1.7e308, 0, 0), new Vector3d(1e308, 0, 0), Vector3d.Zero, 1);
            var segment = new HermiteSegment(start, new StateDerivative(start.Velocity, Vector3d.Zero, Vector3d.Zero),
                end, new StateDerivative(end.Velocity, Vector3d.Zero, Vector3d.Zero));
            FlightState middle = segment.StateAt(0.5);
            Assert.That(middle.IsFinite, Is.True, middle.ToString());
            Assert.That(middle.Position.X, Is.EqualTo(1.7e308).Within(1e-12 * 1.7e308));
            // Where the cubic itself overshoots what a double holds (1.7e308 + 2 x 1e308/8 = 1.95e308), the nearest finite value.
            var rising = new FlightState(new Vector3d(1.7e308, 0, 0), new Vector3d(-1e308, 0, 0), Vector3d.Zero, 1);
            var overshoot = new HermiteSegment(start, new StateDerivative(start.Velocity, Vector3d.Zero, Vector3d.Zero),
                rising, new StateDerivative(rising.Velocity, Vector3d.Zero, Vector3d.Zero));
            Assert.That(overshoot.StateAt(0.5).Position.X, Is.EqualTo(double.MaxValue));
            // An ordinary step is the plain formula, bit for bit (the scaled path is only taken on overflow).
            var a = new FlightState(new Vector3d(1, 2, 3), new Vector3d(4, 5, 6), new Vector3d(7, 8, 9), 0);
            var b = new FlightState(new Vector3d(2, 3, 1), new Vector3d(3, 2, 1), new Vector3d(9, 8, 7), 0.25);
            var da = new StateDerivative(a.Velocity, new Vector3d(-1, 0, -9.8), new Vector3d(0.1, 0.2, 0.3));
            var db = new StateDerivative(b.Velocity, new Vector3d(-2, 1, -9.8), new Vector3d(0.3, 0.2, 0.1));
            var ordinary = new HermiteSegment(a, da, b, db);
            double t = 0.1, h = 0.25, sFraction = t / h;
            double s2 = sFraction * sFraction, s3 = s2 * sFraction;
            double plain = (2 * s3 - 3 * s2 + 1) * a.Position.Y + (s3 - 2 * s2 + sFraction) * (a.Velocity.Y * h) + (3 * s2 - 2 * s3) * b.Position.Y + (s3 - s2) * (b.Velocity.Y * h);
            Assert.That(ordinary.PositionAt(t).Y, Is.EqualTo(plain));
        }

        [Test]
        public void CutOfAStepBetweenEndsNear1e308_HasAFiniteSlope()
        {
            // Found by the far-aim tests (2026-12-02): a cut's end slope, y0 d00 + m0 d10 + y1 d01 + m1 d11, has y0 d00 and
            // y1 d01 each up to 1.5 |y| (at mid-step), which overflow for ends near 1.7e308 and cancel, inf - inf = NaN; the
            // stepper refused the step that held the event (Diverged). A straight fall from 1.7e308 to 1.6e308 in 1 s: the
            // slope is -1e307 m/s all along.
            var top = new FlightState(new Vector3d(0, 0, 1.7e308), new Vector3d(0, 0, -1e307), Vector3d.Zero, 0);
            var bottom = new FlightState(new Vector3d(0, 0, 1.6e308), new Vector3d(0, 0, -1e307), Vector3d.Zero, 1);
            var fall = new HermiteSegment(top, new StateDerivative(top.Velocity, Vector3d.Zero, Vector3d.Zero),
                bottom, new StateDerivative(bottom.Velocity, Vector3d.Zero, Vector3d.Zero));
            Assert.That(fall.TryUntil(0.5, out HermiteSegment cut), Is.True);
            // The scaled form's rounding: a few units in the last place of the terms it sums, 1.5 x 1.7e308 against a result
            // of 1e307, so 1e-14 relative.
            Assert.That(cut.EndDerivative.Velocity.Z, Is.EqualTo(-1e307).Within(1e-14 * 1e307));
            Assert.That(cut.End.Position.Z, Is.EqualTo(1.65e308).Within(1e-14 * 1.65e308));

            // Ordinary cuts are the plain formula, bit for bit.
            var a = new FlightState(new Vector3d(1, 2, 3), new Vector3d(4, 5, 6), new Vector3d(7, 8, 9), 0);
            var b = new FlightState(new Vector3d(2, 3, 1), new Vector3d(3, 2, 1), new Vector3d(9, 8, 7), 0.25);
            var da = new StateDerivative(a.Velocity, new Vector3d(-1, 0, -9.8), new Vector3d(0.1, 0.2, 0.3));
            var db = new StateDerivative(b.Velocity, new Vector3d(-2, 1, -9.8), new Vector3d(0.3, 0.2, 0.1));
            Assert.That(new HermiteSegment(a, da, b, db).TryUntil(0.1, out HermiteSegment ordinary), Is.True);
            double h = 0.25, sf = 0.1 / h, s2 = sf * sf;
            double plain = (a.Position.Y * (6 * s2 - 6 * sf) + (a.Velocity.Y * h) * (3 * s2 - 4 * sf + 1) + b.Position.Y * (6 * sf - 6 * s2)
                            + (b.Velocity.Y * h) * (3 * s2 - 2 * sf)) / h;
            Assert.That(ordinary.EndDerivative.Velocity.Y, Is.EqualTo(plain));
        }

        [Test]
        public void Crossing_AtMidStepOfAFlightNear1e308Up_IsFound_NotRefused()
        {
            // The same through the stepper: a ball 1.7e308 m up (its height cannot change at that scale) flown at 1/240 s
            // toward a net at x = 11.885 m. At -45 degrees the step holding the crossing was refused as diverged (the cut's
            // slope overflowed); at -44 degrees, the crossing fell where the slope's terms stayed finite.
            var model = new FlightModel(new Ball(0.057, 0.033), new Air(1.21), new Vector3d(0, 0, -9.81));
            var ground = new Plane(new Vector3d(0, 0, -1.7e308), Vector3d.UnitZ);
            var net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            foreach (double degrees in new[] { -45.0, -44.5, -44.0 })
            {
                var stepper = new FlightStepper(model, RungeKutta4.Instance, new FlightEventSet(Vector3d.UnitZ, ground, new[] { net }));
                double e = degrees * Math.PI / 180;
                stepper.Reset(new FlightState(new Vector3d(0, 0, 1.7e308), new Vector3d(30 * Math.Cos(e), 0, 30 * Math.Sin(e)), Vector3d.Zero));
                StepOutcome outcome = StepOutcome.Taken;
                for (int i = 0; i < 1000 && outcome == StepOutcome.Taken && !stepper.IsStopped; i++)
                {
                    outcome = stepper.TryStep(1.0 / 240, FlightEventKinds.Landing | FlightEventKinds.PlaneCrossing);
                }

                Assert.That(stepper.IsStopped, Is.True, $"{degrees} deg: {outcome}");
                Assert.That(stepper.StopEvent.Kind, Is.EqualTo(FlightEventKinds.PlaneCrossing));
                Assert.That(stepper.StopEvent.State.IsFinite, Is.True);
                // The crossing is located to the search's time tolerance; at 30 m/s or less that moves x by under 30 x it.
                Assert.That(stepper.StopEvent.State.Position.X, Is.EqualTo(11.885).Within(30 * HermiteSegment.TimeTolerance));
            }
        }

        [TestCase(1.0)]
        [TestCase(4.149515568880993e+180)] // 2^600: past 1e150, scaled back to exactly the k = 1 numbers
        [TestCase(1.0715086071862673e+301)] // 2^1000
        public void Crossing_OfACubicDipFarFromThePlane_IsFoundAsAtUnitScale(double k)
        {
            // A step whose height above the ground plane is k times the cubic f0 = 1, m0 = -6, f1 = 1, m1 = 5 (h = 1 s): it dips
            // below the plane and comes back (-s^3 + 7 s^2 - 6 s + 1, -0.375 at mid-step), the same dip at every scale. The
            // event search finds it through the cubic's turning points, and their discriminant squares the numbers, which
            // overflows from about 1e154 (k = 2^600 and 2^1000): the turning points were lost and, both ends being above the
            // plane, the crossing was missed. Now numbers past 1e150 are scaled first.
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            HermiteSegment unit = Fall(1);
            Assert.That(unit.TryFindCrossing(ground, CrossingDirection.AgainstNormal, out double expected), Is.True);
            HermiteSegment scaled = Fall(k);
            Assert.That(scaled.TryFindCrossing(ground, CrossingDirection.AgainstNormal, out double time), Is.True, $"k = {k}");
            // 2^600 is scaled back to the very same numbers: the same time to the bit; 2^1000 to the search's tolerance.
            Assert.That(time, k == 4.149515568880993e+180 ? Is.EqualTo(expected) : Is.EqualTo(expected).Within(HermiteSegment.TimeTolerance));
            Assert.That(HermiteSegment.SurelyNoCrossing(ground, CrossingDirection.AgainstNormal, scaled.Start, scaled.StartDerivative, scaled.End,
                scaled.EndDerivative), Is.False, "the quick test before the segment is built must not rule it out");
        }

        [Test]
        public void Crossing_OfAPlaneBetweenEndsNear1e308_IsFound()
        {
            // The linear fall through a plane 8e307 m above and below (speed -1.6e308 m/s): the four numbers are finite but
            // sum to -3.2e308, and the test of their sum called the cubic not finite, with no crossing.
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            var top = new FlightState(new Vector3d(0, 0, 8e307), new Vector3d(0, 0, -1.6e308), Vector3d.Zero, 0);
            var bottom = new FlightState(new Vector3d(0, 0, -8e307), new Vector3d(0, 0, -1.6e308), Vector3d.Zero, 1);
            var straight = new HermiteSegment(top, new StateDerivative(top.Velocity, Vector3d.Zero, Vector3d.Zero),
                bottom, new StateDerivative(bottom.Velocity, Vector3d.Zero, Vector3d.Zero));
            Assert.That(straight.TryFindCrossing(ground, CrossingDirection.AgainstNormal, out double middle), Is.True);
            Assert.That(middle, Is.EqualTo(0.5).Within(HermiteSegment.TimeTolerance));
        }

        [TestCase(1e-300, -1e151, false, true)] // starts just above the plane: a crossing at once
        [TestCase(1e151, 1e-300, false, false)] // ends just above the plane: no crossing
        [TestCase(-1e-300, -1e151, true, false)] // a flight starting just below the plane: no landing at its start
        public void Crossing_OfAFallWithAnEndWithin1e300OfThePlane_IsAsUnscaled(double startHeight, double endHeight, bool startsFlight, bool crosses)
        {
            // A linear fall at 1e151 m/s for 1 s, one end 1e-300 m from the plane: its numbers sum past 1e150 and are scaled by
            // 2^-600 before the search, and 1e-300 times 2^-600 rounds to 0, which put that end on the plane: the crossing
            // from just above was missed (the search needs a start above 0), an end just above the plane was a landing
            // (f1 <= 0), and a flight starting just below it landed at its start (the f0 == 0 rule). The unscaled cubic's
            // answer, which the code before the scaling gave: the ends' signs decide. Found in review, 2026-12-02.
            var ground = new Plane(Vector3d.Zero, Vector3d.UnitZ);
            var start = new FlightState(new Vector3d(0, 0, startHeight), new Vector3d(0, 0, -1e151), Vector3d.Zero, 0);
            var end = new FlightState(new Vector3d(0, 0, endHeight), new Vector3d(0, 0, -1e151), Vector3d.Zero, 1);
            var fall = new HermiteSegment(start, new StateDerivative(start.Velocity, Vector3d.Zero, Vector3d.Zero),
                end, new StateDerivative(end.Velocity, Vector3d.Zero, Vector3d.Zero));
            Assert.That(fall.TryFindCrossing(ground, CrossingDirection.AgainstNormal, startsFlight, out double time), Is.EqualTo(crosses));
            if (crosses)
            {
                // The true crossing is 1e-451 s after the start: the search's tolerance from it.
                Assert.That(time, Is.EqualTo(0).Within(HermiteSegment.TimeTolerance));
            }
        }

        private static HermiteSegment Fall(double k)
        {
            var start = new FlightState(new Vector3d(0, 0, k), new Vector3d(0, 0, -6 * k), Vector3d.Zero, 0);
            var end = new FlightState(new Vector3d(0, 0, k), new Vector3d(0, 0, 5 * k), Vector3d.Zero, 1);
            return new HermiteSegment(start, new StateDerivative(start.Velocity, Vector3d.Zero, Vector3d.Zero),
                end, new StateDerivative(end.Velocity, Vector3d.Zero, Vector3d.Zero));
        }

        [Test]
        public void SignedDistance_FromAPlanePointNear1e308Away_IsTheFiniteTrueDistance()
        {
            // Found in review (2026-12-02): position - Point overflows where the two are near 1e308 apart, and the plain dot
            // product was then NaN (inf * 0 beside a zero normal component, inf - inf) or infinite where the true distance is
            // finite. The form from quarters gives the true distance, and infinity only beyond double.MaxValue.
            var beside = new Plane(new Vector3d(-1e308, 0, 0), Vector3d.UnitZ);
            Assert.That(beside.SignedDistance(new Vector3d(1e308, 0, 5)), Is.EqualTo(5.0)); // was NaN
            var slanted = new Plane(new Vector3d(-1e308, 1e308, 0), new Vector3d(0.6, 0.8, 0));
            double across = slanted.SignedDistance(new Vector3d(1e308, -1e308, 0)); // 2e308 (0.6 - 0.8): was NaN (inf - inf)
            Assert.That(across, Is.EqualTo(-0.4e308).Within(1e-15 * 0.4e308));
            var tilted = new Plane(new Vector3d(-1e308, 0, 0), new Vector3d(0.6, 0, 0.8));
            Assert.That(tilted.SignedDistance(new Vector3d(1e308, 0, 0)), Is.EqualTo(1.2e308).Within(1e-15 * 1.2e308)); // was +infinity
            var facing = new Plane(new Vector3d(-1e308, 0, 0), Vector3d.UnitX);
            Assert.That(facing.SignedDistance(new Vector3d(1e308, 0, 0)), Is.EqualTo(double.PositiveInfinity), "2e308: beyond a double");

            // Ordinary distances are the plain formula, bit for bit.
            var random = new Random(5);
            for (int i = 0; i < 10000; i++)
            {
                var normal = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                if (normal.Length < 0.1)
                {
                    continue;
                }

                var plane = new Plane(new Vector3d(1e3 * (random.NextDouble() - 0.5), 1e3 * (random.NextDouble() - 0.5), random.NextDouble()), normal);
                var point = new Vector3d(1e4 * (random.NextDouble() - 0.5), 1e4 * (random.NextDouble() - 0.5), 1e2 * (random.NextDouble() - 0.5));
                Assert.That(plane.SignedDistance(point), Is.EqualTo(Vector3d.Dot(point - plane.Point, plane.Normal)));
            }
        }

        [Test]
        public void SignedDistance_WhoseProductsOverflowInTheirPartialSum_IsTheFiniteTrueDistance()
        {
            // Found in review (2026-12-02): the halved form's first two products, 1.7e308 (0.55 + 0.55), overflow before the
            // third, -1.7e308 0.6285, is added, so it gave +infinity for a true distance of 1.6e308. Quarters cannot overflow.
            var plane = new Plane(new Vector3d(-1.7e308, -1.7e308, 1.7e308), new Vector3d(0.55, 0.55, Math.Sqrt(1 - 2 * 0.55 * 0.55)));
            Vector3d n = plane.Normal;
            double expected = 2 * (1.7e308 * ((n.X + n.Y) - n.Z)); // 3.4e308 (n.X + n.Y - n.Z), formed without overflow
            double distance = plane.SignedDistance(new Vector3d(1.7e308, 1.7e308, -1.7e308));
            // 1e-15 relative: a handful of roundings of 1.1e-16, the cancellation (n.X + n.Y) - n.Z amplifying n's by 1.73 / 0.47.
            Assert.That(distance, Is.EqualTo(expected).Within(1e-15 * expected));

            // Random points and planes with components up to double.MaxValue: never NaN, and finite wherever the true distance
            // (from eighths, a scale neither path uses) is clearly under double.MaxValue, to 1e-14 of the numbers' size (a dot
            // product of three terms rounds to a few ulp of the sum of their magnitudes, 2.2e-16 each).
            var random = new Random(11);
            double Huge() => (random.NextDouble() * 2 - 1) * double.MaxValue;
            for (int i = 0; i < 100000; i++)
            {
                var normal = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                if (normal.Length < 0.1)
                {
                    continue;
                }

                var far = new Plane(new Vector3d(Huge(), Huge(), Huge()), normal);
                var point = new Vector3d(Huge(), Huge(), Huge());
                Vector3d u = far.Normal, o = far.Point;
                double eighth = (0.125 * point.X - 0.125 * o.X) * u.X + (0.125 * point.Y - 0.125 * o.Y) * u.Y + (0.125 * point.Z - 0.125 * o.Z) * u.Z;
                double size = Math.Abs(0.125 * point.X - 0.125 * o.X) * Math.Abs(u.X) + Math.Abs(0.125 * point.Y - 0.125 * o.Y) * Math.Abs(u.Y) +
                    Math.Abs(0.125 * point.Z - 0.125 * o.Z) * Math.Abs(u.Z);
                double d = far.SignedDistance(point);
                Assert.That(double.IsNaN(d), Is.False, $"{far} {point}");
                if (Math.Abs(eighth) < 0.124 * double.MaxValue)
                {
                    Assert.That(0.125 * d, Is.EqualTo(eighth).Within(1e-14 * size), $"{far} {point}");
                }
                else if (Math.Abs(eighth) > 0.126 * double.MaxValue)
                {
                    Assert.That(d, Is.EqualTo(eighth > 0 ? double.PositiveInfinity : double.NegativeInfinity), $"{far} {point}");
                }
            }
        }

        [Test]
        public void Project_WhereTheDistanceExceedsADouble_IsTheFiniteFoot()
        {
            // Found in review (2026-12-02): Project is position - Normal * SignedDistance, and a distance beyond double.MaxValue
            // (2e308 here) times a zero normal component is NaN (inf * 0), and times a non-zero one infinite where the foot is
            // finite. The foot of (1e308, 5, 0) on the plane x = -1e308 is (-1e308, 5, 0).
            var wall = new Plane(new Vector3d(-1e308, 0, 0), Vector3d.UnitX);
            Vector3d foot = wall.Project(new Vector3d(1e308, 5, -3));
            Assert.That(foot.X, Is.EqualTo(-1e308)); // was -infinity
            Assert.That(foot.Y, Is.EqualTo(5.0)); // was NaN
            Assert.That(foot.Z, Is.EqualTo(-3.0)); // was NaN

            // Tilted: a distance of 2.8e308; the foot (1e308 - 0.6 2.8e308, 1e308 - 0.8 2.8e308) = (-0.68e308, -1.24e308, 7).
            var slope = new Plane(new Vector3d(-1e308, -1e308, 0), new Vector3d(0.6, 0.8, 0));
            Vector3d tilted = slope.Project(new Vector3d(1e308, 1e308, 7));
            // 1e-15 relative: a few roundings (2.2e-16 each) of numbers near 1e308 (the normal's 0.6, 0.8 are rounded once).
            Assert.That(tilted.X, Is.EqualTo(-0.68e308).Within(1e-15 * 1e308));
            Assert.That(tilted.Y, Is.EqualTo(-1.24e308).Within(1e-15 * 1e308));
            Assert.That(tilted.Z, Is.EqualTo(7.0));

            // Random planes and points up to double.MaxValue: never NaN; where finite, on the plane (its distance within 1e-14 of
            // the numbers' size: a few roundings each of the foot and of the distance).
            var random = new Random(13);
            double Huge() => (random.NextDouble() * 2 - 1) * double.MaxValue;
            for (int i = 0; i < 100000; i++)
            {
                var normal = new Vector3d(random.Next(3) == 0 ? 0 : random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                if (normal.Length < 0.1)
                {
                    continue;
                }

                var far = new Plane(new Vector3d(Huge(), Huge(), Huge()), normal);
                var point = new Vector3d(Huge(), Huge(), Huge());
                Vector3d projected = far.Project(point);
                Assert.That(double.IsNaN(projected.X) || double.IsNaN(projected.Y) || double.IsNaN(projected.Z), Is.False, $"{far} {point}");
                if (far.Normal.X == 0)
                {
                    Assert.That(projected.X, Is.EqualTo(point.X), "a zero normal component leaves the position's");
                }

                if (projected.IsFinite)
                {
                    Assert.That(0.25 * far.SignedDistance(projected), Is.EqualTo(0).Within(1e-14 * 0.25 * double.MaxValue), $"{far} {point}");
                }
            }
        }

        [Test]
        public void Landing_FarAlongAGroundWhosePointIsNear1e308Away_IsFound_ByTheStepperAndTheBatchAlike()
        {
            // A ball 1 m above a ground plane whose given point lies 2e308 m away along the ground: the landing's signed distance
            // was NaN at every step, so the ball fell through the ground. Now the stepper lands it, and the batch (which tests
            // its own vector bound first and must send such a lane to the scalar finish) lands it at the same state.
            FlightModel model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var ground = new Plane(new Vector3d(-1e308, 0, 0), Vector3d.UnitZ);
            var start = new FlightState(new Vector3d(1e308, 0, 1), new Vector3d(-5, 0, 2), new Vector3d(0, 100, 0), 0);
            var stepper = new FlightStepper(model, RungeKutta4.Instance, new FlightEventSet(model.Up, ground));
            stepper.Reset(start);
            var batch = new BallBatch(model, 1, ground);
            batch.Add(start);
            FlightEvent landing = default;
            bool landed = false;
            for (int i = 0; i < 480 && !landed; i++)
            {
                stepper.TryStep(1.0 / 240, FlightEventKinds.Landing);
                landed = stepper.TryGetEvent(FlightEventKinds.Landing, out landing);
            }

            Assert.That(landed, Is.True, "the stepper lands the ball within 2 s");
            Assert.That(landing.State.Position.Z, Is.EqualTo(0).Within(1e-9));
            batch.Advance(1.0 / 240, 480);
            Assert.That(batch.TryGetLanding(0, out FlightState batchLanding), Is.True, "the batch lands it too");
            Assert.That(batchLanding.Position.Z, Is.EqualTo(landing.State.Position.Z));
            Assert.That(batchLanding.Time, Is.EqualTo(landing.State.Time));
            Assert.That(batchLanding.Velocity.Z, Is.EqualTo(landing.State.Velocity.Z));

            // The adaptive steps (the aim solvers' trials) locate it on their own interpolant, through the same distance.
            var adaptive = new FlightStepper(model, RungeKutta4.Instance, new FlightEventSet(model.Up, ground));
            adaptive.Reset(start);
            var method = new DormandPrince54();
            bool adaptiveLanded = false;
            for (int i = 0; i < 1000 && !adaptiveLanded; i++)
            {
                adaptive.TryStepAdaptive(method, 0.1, FlightEventKinds.Landing);
                adaptiveLanded = adaptive.TryGetEvent(FlightEventKinds.Landing, out FlightEvent adaptiveLanding) &&
                    Math.Abs(adaptiveLanding.State.Position.Z) < 1e-9 && Math.Abs(adaptiveLanding.Time - landing.Time) < 1e-6;
            }

            Assert.That(adaptiveLanded, Is.True, "the adaptive stepper lands it at the same time (to 1e-6 s)");
        }

        [Test]
        public void Reset_RefusedOnTheSurface_KeepsTheCounters()
        {
            // Reset zeroed the counters before it found the roll it starts non-finite, so a refused Reset changed them.
            var air = new Air(1e300);
            FlightModel model = SportPresets.Soccer.CreateModel(air, Gravity.ZUp);
            var contact = new GroundContact(CrossBounce.Hard, new Plane(Vector3d.Zero, Vector3d.UnitZ));
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, contact);
            stepper.Reset(new FlightState(new Vector3d(0, 0, 1), new Vector3d(1, 0, 0), Vector3d.Zero));
            long evaluations = stepper.DerivativeEvaluations;
            var onTheSurface = new FlightState(new Vector3d(0, 0, model.Ball.Radius), new Vector3d(1e200, 0, 0), new Vector3d(0, 1e300, 0));
            Assert.Throws<ArgumentException>(() => stepper.Reset(onTheSurface));
            Assert.That(stepper.DerivativeEvaluations, Is.EqualTo(evaluations));
            Assert.That(stepper.State.Position, Is.EqualTo(new Vector3d(0, 0, 1)));
        }

    }
}
