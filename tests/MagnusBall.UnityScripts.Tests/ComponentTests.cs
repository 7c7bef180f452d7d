using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using MagnusBall.Components;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using MagnusBall.Tests;
using MagnusBall.UnityStubs;
using NUnit.Framework;
using UnityEngine;
using static MagnusBall.UnityScripts.Tests.UnityLoop;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The package's MagnusBall.Unity components on the UnityEngine stub: the flight component lands where
    /// the core's FixedStepDriver does, to the bit; its events fire once each, in order; the trajectory
    /// preview is the path flown, re-predicted only when the launch changes, and allocates nothing per frame.
    /// </summary>
    [TestFixture]
    [NonParallelizable] // the stub's Time is static, as Unity's is
    public class ComponentTests
    {
        private static readonly Vector3 Velocity = new Vector3(24f, 6f, 1.5f);
        private static readonly Vector3 SpinVector = new Vector3(10f, -20f, -250f);
        private static readonly Vector3 Start = new Vector3(-10f, 1.2f, 0.5f);

        private static MagnusBallFlight NewFlight(SurfaceChoice surface, StepIn stepIn = StepIn.Update, bool watchNet = false)
        {
            var holder = new GameObject("ball");
            holder.transform.position = Start;
            MagnusBallFlight flight = Add<MagnusBallFlight>(holder);
            flight.settings.surface = surface;
            flight.stepIn = stepIn;
            flight.watchPlane = watchNet;
            flight.ApplySettings();
            return flight;
        }

        /// <summary>What the inspector's defaults mean, built independently from the core's public API.</summary>
        private static FixedStepDriver ReferenceDriver(IBounceModel? bounce, bool watchNet = false)
        {
            FlightModel model = SportPresets.Tennis.CreateModel(new Air((double)(float)Air.SeaLevelDensity), Gravity.YUp);
            var up = new Vector3d(0, 1, 0);
            var ground = new Plane(up * model.Ball.Radius, up);
            FlightEventSet events = watchNet
                ? new FlightEventSet(up, ground, new[] { new Plane(Vector3d.Zero, new Vector3d(1, 0, 0)) })
                : new FlightEventSet(up, ground);
            var start = new FlightState(new Vector3d(Start.x, Start.y, Start.z), new Vector3d(Velocity.x, Velocity.y, Velocity.z), new Vector3d(SpinVector.x, SpinVector.y, SpinVector.z));
            return new FixedStepDriver(model, RungeKutta4.Instance, (double)(1f / 240f), start, events, bounce, (double)0.25f);
        }

        private static List<FlightEvent> Record(MagnusBallFlight flight)
        {
            var seen = new List<FlightEvent>();
            flight.Landed += seen.Add;
            flight.Bounced += seen.Add;
            flight.PlaneCrossed += seen.Add;
            flight.ApexReached += seen.Add;
            flight.Stopped += seen.Add;
            return seen;
        }

        private static void Fly(MagnusBallFlight flight, float frameDelta, int maxFrames = 200_000)
        {
            StubControl.DeltaTime = frameDelta;
            for (int frame = 0; frame < maxFrames && flight.IsFlying; frame++)
            {
                if (flight.stepIn == StepIn.FixedUpdate)
                {
                    Call(flight, "FixedUpdate");
                }

                Call(flight, "Update");
            }

            Assert.That(flight.IsFlying, Is.False, "the flight ends");
        }

        private static List<FlightEvent> ReferenceEvents(FixedStepDriver driver)
        {
            var all = new List<FlightEvent>();
            var buffer = new FlightEvent[16];
            for (int i = 0; i < 1_000_000 && !driver.IsFinished; i++)
            {
                AdvanceResult r = driver.Advance(driver.FixedStep, buffer);
                for (int k = 0; k < r.EventCount; k++)
                {
                    all.Add(buffer[k]);
                }
            }

            return all;
        }

        [TestCase(1f / 60f, StepIn.Update)]
        [TestCase(1f / 144f, StepIn.Update)]
        [TestCase(0f, StepIn.FixedUpdate)]
        public void ALaunch_LandsOnTheSameBitsAsTheDriver(float frameDelta, StepIn stepIn)
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, stepIn);
            Time.fixedDeltaTime = 1f / 240f;
            List<FlightEvent> seen = Record(flight);
            flight.Launch(Velocity, SpinVector);
            Fly(flight, frameDelta);

            FlightEvent landing = ReferenceEvents(ReferenceDriver(null)).Find(e => e.Kind == FlightEventKinds.Landing);
            FlightEvent landed = seen.Find(e => e.Kind == FlightEventKinds.Landing);
            Assert.That(landed.Position, Is.EqualTo(landing.Position), "bitwise: same model, integrator, step and events as the driver");
            Assert.That(landed.Time, Is.EqualTo(landing.Time));
            Assert.That(landed.State.Velocity, Is.EqualTo(landing.State.Velocity));
            TestContext.Out.WriteLine($"lands at {landed.Position}, t = {landed.Time:R} s");
        }

        [Test]
        public void ThePresetDropDown_HasEveryPreset_ByItsName()
        {
            // The drop-down is the list a designer picks from: every name SportPresets.FromName accepts, each once.
            var names = new List<string>();
            foreach (PresetChoice choice in (PresetChoice[])Enum.GetValues(typeof(PresetChoice)))
            {
                names.Add(FlightSettings.PresetName(choice));
                var settings = new FlightSettings { presetChoice = choice };
                Assert.That(settings.Preset().Name, Is.EqualTo(FlightSettings.PresetName(choice)), choice.ToString());
                Assert.That(settings.preset, Is.EqualTo(settings.Preset().Name));
            }

            Assert.That(names, Is.EquivalentTo(SportPresets.Names));
        }

        [Test]
        public void ThePresetByName_StillWorks_AndRefusesAnUnknownNameAtOnce()
        {
            var settings = new FlightSettings();
            settings.preset = "Table_Tennis";
            Assert.That(settings.presetChoice, Is.EqualTo(PresetChoice.TableTennis));
            var e = Assert.Throws<ArgumentException>(() => settings.preset = "squash")!;
            Assert.That(e.ParamName, Is.EqualTo("preset"));
            Assert.That(e.Message, Does.Contain("table-tennis").And.Contain("squash"));
            Assert.That(settings.presetChoice, Is.EqualTo(PresetChoice.TableTennis), "unchanged");
        }

        [TestCase("soccer", PresetChoice.Soccer)]
        [TestCase("golf-linear-2023", PresetChoice.GolfLinear2023)]
        [TestCase("Table Tennis", PresetChoice.TableTennis)]
        public void AnOldScenesPresetText_BecomesTheDropDownsValue(string oldText, PresetChoice expected)
        {
            var settings = new FlightSettings();
            LoadOldPreset(settings, oldText);
            Assert.That(settings.presetChoice, Is.EqualTo(expected));
            Assert.That(settings.Preset().Name, Is.EqualTo(FlightSettings.PresetName(expected)));
        }

        [Test]
        public void AnOldScenesUnknownPresetText_IsRefusedNamingIt_UntilAPresetIsPicked()
        {
            var settings = new FlightSettings();
            LoadOldPreset(settings, "squash");
            var e = Assert.Throws<ArgumentException>(() => settings.Preset())!;
            Assert.That(e.ParamName, Is.EqualTo("preset"));
            Assert.That(e.Message, Does.Contain("'squash'").And.Contain("drop-down"));
            settings.presetChoice = PresetChoice.Soccer; // picked in the inspector
            Assert.That(settings.Preset().Name, Is.EqualTo("soccer"));
            ((ISerializationCallbackReceiver)settings).OnBeforeSerialize();
            Assert.That(settings.preset, Is.EqualTo("soccer"));
        }

        [Test]
        public void ASubnormalSpin_LeavesTheDrawnRotationFinite()
        {
            // rotateWithSpin turned the ball about w / |w|, which divides by multiplying with 1/|w|: +inf for |w| below
            // 1/double.MaxValue = 5.6e-309 rad/s, so the axis was (inf, NaN, NaN) and the transform's rotation NaN from the
            // first frame (a finite launch). The turn there is 0 degrees: the rotation must stay the identity.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            StubControl.DeltaTime = 1f / 60f;
            var start = new FlightState(new Vector3d(Start.x, Start.y, Start.z), new Vector3d(Velocity.x, Velocity.y, Velocity.z), new Vector3d(1e-310, 0, 0));
            flight.Launch(start);
            for (int frame = 0; frame < 5; frame++)
            {
                Call(flight, "Update");
            }

            Quaternion r = flight.transform.rotation;
            Assert.That(flight.IsFlying, Is.True);
            Assert.That((r.x, r.y, r.z, r.w), Is.EqualTo((0f, 0f, 0f, 1f)), "a 0-degree turn about a unit axis");
        }

        [Test]
        public void AfterTheFlight_TheBallIsDrawnWhereItEnded()
        {
            // The driver draws the ball a step behind the simulation, so the frame that takes the landing step can leave the
            // render time short of the landing (frames shorter than the 1/240 s step, or not a multiple of it). Before, the
            // component stopped passing frame time to the driver once the flight ended, and the ball stayed drawn there, short
            // of its landing point, for good (4.5 cm here); now the drawn ball runs on to the landing (the driver takes no step).
            // Frames of 1 ms: 1000 FPS.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            flight.Launch(Velocity, SpinVector);
            Fly(flight, 0.001f);
            FixedStepDriver driver = flight.Driver!;
            Assert.That(driver.RenderTime, Is.LessThan(driver.State.Time), "the landing frame leaves the render time short of the landing");
            long steps = driver.TotalSteps;
            for (int i = 0; i < 10; i++)
            {
                Call(flight, "Update");
            }

            Vector3 drawn = flight.transform.position, landed = UnityFrame.ToUnity(driver.State.Position);
            Assert.That((drawn.x, drawn.y, drawn.z), Is.EqualTo((landed.x, landed.y, landed.z)), "drawn at the landing");
            Assert.That(driver.TotalSteps, Is.EqualTo(steps), "no step after the end");
            Assert.That(flight.IsFlying, Is.False);
        }

        [Test]
        public void TheEvents_FireOnceEach_InTimeOrder_AsTheDriverReportsThem()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.Preset, watchNet: true); // tennis preset: hard court
            List<FlightEvent> seen = Record(flight);
            flight.Launch(Velocity, SpinVector);
            Fly(flight, 1f / 60f);

            List<FlightEvent> expected = ReferenceEvents(ReferenceDriver(CrossBounce.Hard, watchNet: true));
            Assert.That(seen.Count, Is.EqualTo(expected.Count), "one call per event");
            for (int i = 0; i < seen.Count; i++)
            {
                Assert.That((seen[i].Kind, seen[i].Time, seen[i].Position), Is.EqualTo((expected[i].Kind, expected[i].Time, expected[i].Position)), $"event {i}");
                if (i > 0)
                {
                    Assert.That(seen[i].Time, Is.GreaterThanOrEqualTo(seen[i - 1].Time), "time order");
                }
            }

            Assert.That(seen.FindAll(e => e.Kind == FlightEventKinds.PlaneCrossing).Count, Is.EqualTo(1), "the net once");
            Assert.That(seen.FindAll(e => e.Kind == FlightEventKinds.Bounce).Count, Is.GreaterThanOrEqualTo(2));
            Assert.That(seen.FindAll(e => e.Kind == FlightEventKinds.Rest).Count, Is.EqualTo(1));
            Assert.That(seen[seen.Count - 1].Kind, Is.EqualTo(FlightEventKinds.Rest), "the stop ends it");
            Assert.That(seen.FindAll(e => e.Kind == FlightEventKinds.Landing), Is.Empty, "with a bounce model the ball bounces, it does not land");
            Assert.That(seen.FindIndex(e => e.Kind == FlightEventKinds.PlaneCrossing), Is.LessThan(seen.FindIndex(e => e.Kind == FlightEventKinds.Bounce)), "over the net, then the bounce");
        }

        [TestCase(20f, 20f)]
        [TestCase(0.25f, 0.25f)]
        [TestCase(1f, 2f)]
        public void EveryEvent_IsRaised_EvenWhenAFrameHoldsMoreThanSixteen(float frameDelta, float clamp)
        {
            // A review's probe: the component wrote events into a 16-slot buffer and dropped the rest, so a frame holding many
            // (a ball bouncing to rest through a long hitch) lost bounces and even the stop: one 20 s frame raised 8 of 25
            // bounces and no Stopped. The buffer now holds any step's events, the driver defers the rest of a frame that might
            // overflow it (AdvanceResult.StepsDeferred), and the component takes that time after raising the events.
            var holder = new GameObject("ball");
            holder.transform.position = new Vector3(-10f, 1.2f, 0.5f);
            MagnusBallFlight flight = Add<MagnusBallFlight>(holder);
            flight.settings.surface = SurfaceChoice.Hard;
            flight.maxFrameDelta = clamp;
            flight.ApplySettings();
            List<FlightEvent> seen = Record(flight);
            flight.Launch(new Vector3(6f, 8f, 0f), Vector3.zero);
            StubControl.DeltaTime = frameDelta;
            for (int frame = 0; frame < 10_000 && flight.IsFlying; frame++)
            {
                Call(flight, "Update");
            }

            FixedStepDriver driver = flight.Driver!;
            Assert.That(flight.IsFlying, Is.False, "the flight ended");
            Assert.That(seen.FindAll(e => e.Kind == FlightEventKinds.Rest).Count, Is.EqualTo(1), "Stopped once");
            Assert.That(seen.FindAll(e => e.Kind == FlightEventKinds.Bounce).Count, Is.EqualTo(driver.Bounces), "every bounce the driver counted");
            Assert.That(driver.Bounces, Is.GreaterThan(16), "more bounces than the old buffer held");
            Assert.That(flight.ArcVersion, Is.EqualTo(driver.Bounces + 1), "one arc per launch and bounce (the preview follows each)");
        }

        [Test]
        public void ALaunchBelowTheGround_IsRefused_AndOneOnItInFloats_IsLiftedOntoIt()
        {
            // A review's probe: a landing is a crossing of the touchdown plane (groundHeight + radius) from above, so a ball
            // whose centre started below it (a GameObject at the origin with groundHeight 0) fell for ever, y = -13706 m after
            // ten minutes. Deeper than 0.1 mm it is now refused; within it (a float position meant to be on the plane) the
            // start is lifted onto the plane and the flight lands.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            flight.transform.position = new Vector3(0f, 0f, 0f);
            var e = Assert.Throws<ArgumentException>(() => flight.Launch(new Vector3(20f, 0f, 0f), Vector3.zero))!;
            Assert.That(e.ParamName, Is.EqualTo("start"));
            Assert.That(e.Message, Does.Contain("below the ground plane"));
            Assert.That(flight.IsFlying, Is.False, "nothing launched");

            double radius = SportPresets.Tennis.Ball.Radius;
            flight.transform.position = new Vector3(0f, (float)radius, 0f); // 0.033f: 2e-10 m below 0.033
            Assert.That((double)(float)radius, Is.LessThan(radius), "the float position is below the plane");
            flight.Launch(new Vector3(20f, -1f, 0f), Vector3.zero); // heading down at once
            Assert.That(flight.Driver!.State.Position.Y, Is.EqualTo(radius), "lifted onto the plane");
            Fly(flight, 1f / 60f);
            Assert.That(flight.Driver.IsFinished, Is.True, "it lands");

            // On a tilted ground (given through Configure) the lift leaves the start on or above the plane, never a
            // rounding below it, and the flight lands.
            var up = new Vector3d(0.3, 1, -0.2).NormalizedOrZero();
            var tilted = new Plane(new Vector3d(1.7, 0.4, -2.3), up);
            FlightModel model = SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.YUp);
            flight.Configure(model, RungeKutta4.Instance, 1.0 / 240, new FlightEventSet(new Vector3d(0, 1, 0), tilted), null);
            for (int k = 1; k <= 50; k++)
            {
                Vector3d onIt = tilted.Point + new Vector3d(0.37 * k, 0, 0.11 * k) - up * (Vector3d.Dot(new Vector3d(0.37 * k, 0, 0.11 * k), up) + k * 1.7e-6);
                flight.Launch(new FlightState(onIt, new Vector3d(5, -2, 1), Vector3d.Zero));
                Assert.That(tilted.SignedDistance(flight.Driver!.State.Position), Is.GreaterThanOrEqualTo(0), $"start {k}");
            }

            Fly(flight, 1f / 60f);
            Assert.That(flight.Driver!.IsFinished, Is.True, "it lands on the tilted ground");
        }

        [Test]
        public void LaunchWithAConfiguration_IsAllOrNothing()
        {
            // Configure then Launch(start): a refused start left the new configuration in place. The one-call form changes
            // nothing when either part is refused, and is Configure + Launch when both are accepted.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            flight.Launch(Velocity, SpinVector);
            FixedStepDriver first = flight.Driver!;
            FlightModel oldModel = flight.Model;
            FlightEventSet oldEvents = flight.EventSet;
            double oldStep = flight.FixedStep;
            IIntegrator oldIntegrator = flight.Integrator;
            IBounceModel? oldBounce = flight.BounceModel;
            double oldClamp = first.MaxFrameDeltaSeconds;

            FlightModel model = SportPresets.Soccer.CreateModel(Air.SeaLevel, Gravity.YUp);
            var events = new FlightEventSet(new Vector3d(0, 1, 0), new Plane(new Vector3d(0, 0.11, 0), new Vector3d(0, 1, 0)));
            var belowTheGround = new FlightState(new Vector3d(0, -1, 0), new Vector3d(20, 0, 0), Vector3d.Zero);
            var e = Assert.Throws<ArgumentException>(() => flight.Launch(belowTheGround, model, SemiImplicitEuler.Instance, 1.0 / 120, events, null, 0.1))!;
            Assert.That(e.ParamName, Is.EqualTo("start"));
            var notFinite = new FlightState(new Vector3d(0, 1, 0), new Vector3d(double.NaN, 0, 0), Vector3d.Zero);
            e = Assert.Throws<ArgumentException>(() => flight.Launch(notFinite, model, RungeKutta4.Instance, 1.0 / 120, events, null))!;
            Assert.That(e.ParamName, Is.EqualTo("start"));
            var good = new FlightState(new Vector3d(0, 1, 0), new Vector3d(20, 5, 0), Vector3d.Zero);
            e = Assert.Throws<ArgumentOutOfRangeException>(() => flight.Launch(good, model, RungeKutta4.Instance, 0.5, events, null, 0.25))!;
            Assert.That(e.ParamName, Is.EqualTo("fixedStep"));
            Assert.Throws<ArgumentNullException>(() => flight.Launch(good, null!, RungeKutta4.Instance, 1.0 / 120, events, null));
            Assert.That(flight.Driver, Is.SameAs(first), "the flight goes on");
            Assert.That(flight.Model, Is.SameAs(oldModel));
            Assert.That(flight.EventSet, Is.SameAs(oldEvents));
            Assert.That(flight.FixedStep, Is.EqualTo(oldStep));
            Assert.That(flight.Integrator, Is.SameAs(oldIntegrator));
            Assert.That(flight.BounceModel, Is.SameAs(oldBounce));
            flight.Launch(Velocity, SpinVector); // a relaunch takes the configuration in place: the old frame clamp
            Assert.That(flight.Driver!.MaxFrameDeltaSeconds, Is.EqualTo(oldClamp));
            first = flight.Driver;

            flight.Launch(good, model, RungeKutta4.Instance, 1.0 / 120, events, null);
            Assert.That(flight.Driver, Is.Not.SameAs(first));
            Assert.That(flight.Driver!.State, Is.EqualTo(good));
            Assert.That(flight.Model, Is.SameAs(model));
            Assert.That(flight.EventSet, Is.SameAs(events));
            Assert.That(flight.FixedStep, Is.EqualTo(1.0 / 120));
            Assert.That(flight.BounceModel, Is.Null);
        }

        [Test]
        public void BelowTheGround_RisingLaunchesAndBouncingBalls_AreLeftAsGiven_AndAHandlerMayCancel()
        {
            // A second review: the first version refused every start below the plane, but a rising launch without a bounce
            // model comes down through it and lands, and with a bounce model the core puts the ball onto the court.
            MagnusBallFlight rising = NewFlight(SurfaceChoice.None);
            rising.transform.position = Vector3.zero;
            FlightEvent landed = default;
            rising.Landed += e => landed = e;
            rising.Launch(new Vector3(10f, 8f, 0f), Vector3.zero);
            Fly(rising, 1f / 60f);
            Assert.That(landed.Kind, Is.EqualTo(FlightEventKinds.Landing), "it lands");

            MagnusBallFlight rolling = NewFlight(SurfaceChoice.Hard);
            rolling.transform.position = Vector3.zero;
            int stopped = 0;
            rolling.Stopped += e => stopped++;
            rolling.Launch(new Vector3(5f, 0f, 0f), Vector3.zero);
            // The core put the ball onto the court, rolling; the arc (the preview's start) and the transform start there too,
            // not at the start given one radius below (a review found them left there).
            Assert.That(rolling.Driver!.State.Position.Y, Is.GreaterThan(0), "moved onto the court");
            Assert.That(rolling.ArcStart, Is.EqualTo(rolling.Driver.State));
            Assert.That(rolling.transform.position.y, Is.EqualTo((float)rolling.Driver.State.Position.Y));
            Fly(rolling, 1f / 60f);
            Assert.That(stopped, Is.EqualTo(1), "it rolls to a stop on the court");

            // A Landed handler that cancels: Update read the driver after the step and threw (NullReferenceException).
            MagnusBallFlight cancelled = NewFlight(SurfaceChoice.None);
            cancelled.Landed += e => cancelled.Cancel();
            cancelled.Launch(Velocity, SpinVector);
            StubControl.DeltaTime = 1f / 60f;
            for (int frame = 0; frame < 10_000 && cancelled.IsFlying; frame++)
            {
                Assert.DoesNotThrow(() => Call(cancelled, "Update"));
            }

            Assert.That(cancelled.Driver, Is.Null, "cancelled at the landing");
        }

        [Test]
        public void AHugeSpin_TurnsTheDrawnBallByAFiniteRotation()
        {
            // The turn rate * dt in degrees overflowed a float for a huge but finite spin (3e38 rad/s about each axis), and
            // AngleAxis(infinity) is a NaN rotation; it is now taken modulo a turn first.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            StubControl.DeltaTime = 1f / 60f;
            flight.Launch(new FlightState(new Vector3d(Start.x, Start.y, Start.z), new Vector3d(20, 5, 0), new Vector3d(3e38, 3e38, 3e38)));
            Call(flight, "Update");
            Quaternion r = flight.transform.rotation;
            Assert.That(float.IsNaN(r.x) || float.IsNaN(r.y) || float.IsNaN(r.z) || float.IsNaN(r.w), Is.False, $"{r.x} {r.y} {r.z} {r.w}");
        }

        [Test]
        public void SpinByEffect_TopspinDips_SidespinCurlsLeft_InUnitysFrame()
        {
            var v = new Vector3(25f, 4f, 0f); // along +x: Unity's left of +x is +z (left-handed, y up)
            Vector3d Landing(float topspin, float sidespin)
            {
                MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
                FlightEvent landed = default;
                flight.Landed += e => landed = e;
                flight.Launch(v, topspin, sidespin);
                Fly(flight, 1f / 60f);
                return landed.Position;
            }

            Vector3d plain = Landing(0, 0);
            Assert.That(Landing(3000, 0).X, Is.LessThan(plain.X - 0.5), "topspin dips: lands shorter (by metres at 3000 rpm)");
            Assert.That(Landing(-3000, 0).X, Is.GreaterThan(plain.X + 0.5), "backspin floats");
            Assert.That(Landing(0, 2000).Z, Is.GreaterThan(0.2), "sidespin > 0 curls to the left, +z");
            Assert.That(Landing(0, -2000).Z, Is.LessThan(-0.2), "and < 0 to the right");
        }

        [Test]
        public void ABadLaunch_Throws_NamingTheParameter_AndLeavesTheFlight()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            flight.Launch(Velocity, SpinVector);
            FixedStepDriver driver = flight.Driver!;
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => flight.Launch(Velocity, float.NaN, 0f));
            Assert.That(e!.ParamName, Is.EqualTo("topspinRpm"));
            var e2 = Assert.Throws<ArgumentException>(() => flight.Launch(new Vector3(float.PositiveInfinity, 0, 0), SpinVector));
            Assert.That(e2!.ParamName, Is.EqualTo("start"));
            // A vertical launch with spin has no spin axis across the flight: refused as the velocity (it named the
            // core helpers' "direction" or "up", parameters the caller never gave).
            var e4 = Assert.Throws<ArgumentException>(() => flight.Launch(new Vector3(0, 20, 0), 2000f, 0f));
            Assert.That(e4!.ParamName, Is.EqualTo("velocity"));
            var e5 = Assert.Throws<ArgumentException>(() => flight.Launch(new Vector3(0, -5, 0), 0f, -800f));
            Assert.That(e5!.ParamName, Is.EqualTo("velocity"));
            var e6 = Assert.Throws<ArgumentOutOfRangeException>(() => MagnusBallFlight.SpinByEffect(new Vector3d(20, 3, 0), double.NaN, 0));
            Assert.That(e6!.ParamName, Is.EqualTo("topspinRpm"), "a NaN rate added no spin, silently");
            Assert.That(MagnusBallFlight.SpinByEffect(new Vector3d(0, 20, 0), 0, 0), Is.EqualTo(Vector3d.Zero), "no spin: any velocity");
            flight.fixedStep = -1;
            var e3 = Assert.Throws<ArgumentOutOfRangeException>(() => flight.ApplySettings());
            Assert.That(e3!.ParamName, Is.EqualTo("fixedStep"));
            Assert.That(flight.Driver, Is.SameAs(driver));
            Assert.That(flight.IsFlying, Is.True);
            Assert.That(flight.FixedStep, Is.EqualTo((double)(1f / 240f)), "the old configuration stays");
        }

        [Test]
        public void BadInspectorFields_AreRefused_NamingTheField()
        {
            // ApplySettings promised "the message names it" but named the library's parameters: "point" for groundHeight
            // and planePoint alike, "normal", "maxFrameDeltaSeconds", "density" for airDensity, "name" for preset.
            void Refused(string field, Action<MagnusBallFlight> set)
            {
                MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
                set(flight);
                var e = Assert.Throws(Is.InstanceOf<ArgumentException>(), () => flight.ApplySettings())!;
                Assert.That(((ArgumentException)e).ParamName, Is.EqualTo(field));
                Assert.That(e.Message, Does.Contain(field));
            }

            Refused("groundHeight", f => f.groundHeight = float.NaN);
            Refused("groundHeight", f => f.groundHeight = float.PositiveInfinity);
            Refused("maxFrameDelta", f => f.maxFrameDelta = 0f);
            Refused("planePoint", f => { f.watchPlane = true; f.planePoint = new Vector3(float.NaN, 0f, 0f); });
            Refused("planeNormal", f => { f.watchPlane = true; f.planeNormal = Vector3.zero; });
            Refused("airDensity", f => f.settings.airDensity = -1f);
            Refused("preset", f => LoadOldPreset(f.settings, "squash"));
            Refused("radius", f => { f.settings.customBall = true; f.settings.radius = 0f; });
        }

        [Test]
        public void AFixedStepLongerThanTheFrameClamp_IsRefused()
        {
            // Frames are cut to maxFrameDelta, so a longer fixed step is never reached: the ball hung at its start, flying.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None);
            flight.fixedStep = 1f;
            flight.maxFrameDelta = 0.25f;
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => flight.ApplySettings())!;
            Assert.That(e.ParamName, Is.EqualTo("fixedStep"));
            Assert.That(e.Message, Does.Contain("maxFrameDelta"));
            Assert.That(flight.FixedStep, Is.EqualTo((double)(1f / 240f)), "the old configuration stays");
        }

        [Test]
        public void ThePreview_FollowsANewBall_AndRefusesABadDurationOnce()
        {
            // A review's probe: following another ball whose arc version matched the last one seen (a new ball per shot,
            // each at version 1) kept the first ball's line; and maxDuration 0 threw from every LateUpdate.
            var holder = new GameObject("line");
            LineRenderer line = holder.AddComponent<LineRenderer>();
            MagnusBallTrajectoryPreview preview = Add<MagnusBallTrajectoryPreview>(holder);
            StubControl.DeltaTime = 1f / 60f;
            for (int shot = 0; shot < 3; shot++)
            {
                MagnusBallFlight ball = NewFlight(SurfaceChoice.None);
                ball.transform.position = new Vector3(0f, 1f, 5f * shot);
                preview.flight = ball;
                ball.Launch(new Vector3(20f, 4f, 0f), Vector3.zero);
                Call(ball, "Update");
                Call(preview, "LateUpdate");
                Assert.That(preview.Predictions, Is.EqualTo(shot + 1), $"shot {shot} predicted");
                Assert.That(line.GetPosition(0).z, Is.EqualTo(5f * shot), "the line starts at this ball");
            }

            // Cancelling the followed flight clears its line (it stayed drawn).
            Assert.That(line.positionCount, Is.GreaterThan(0));
            preview.flight!.Cancel();
            Call(preview, "LateUpdate");
            Assert.That(line.positionCount, Is.EqualTo(0), "a cancelled flight's arc is cleared");

            preview.followFlight = false;
            preview.maxDuration = 0;
            preview.Show(new FlightState(new Vector3d(0, 1, 0), new Vector3d(20, 5, 0), Vector3d.Zero));
            int thrown = 0;
            for (int i = 0; i < 30; i++)
            {
                try
                {
                    Call(preview, "LateUpdate");
                }
                catch (System.Reflection.TargetInvocationException ex) when (ex.InnerException is ArgumentException)
                {
                    thrown++;
                }
            }

            Assert.That(thrown, Is.EqualTo(1), "refused once for this request, not every frame");
            Assert.That(line.positionCount, Is.EqualTo(0), "nothing drawn for it");
        }

        [Test]
        public void ThePreview_IsThePathFlown_AndIsPredictedOnlyWhenTheLaunchChanges()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.Preset);
            var holder = new GameObject("line");
            LineRenderer line = holder.AddComponent<LineRenderer>();
            MagnusBallTrajectoryPreview preview = Add<MagnusBallTrajectoryPreview>(holder);
            preview.flight = flight;

            // Before the launch: an aim shown through Show, predicted once however many frames pass.
            var aim = new FlightState(new Vector3d(Start.x, Start.y, Start.z), new Vector3d(Velocity.x, Velocity.y, Velocity.z), new Vector3d(SpinVector.x, SpinVector.y, SpinVector.z));
            for (int i = 0; i < 10; i++)
            {
                preview.Show(aim);
                Call(preview, "LateUpdate");
            }

            Assert.That(preview.Predictions, Is.EqualTo(1));
            Assert.That(line.positionCount, Is.EqualTo(preview.PointCount));
            Vector3 end = line.GetPosition(line.positionCount - 1);

            var bounces = new List<FlightEvent>();
            flight.Bounced += bounces.Add;
            flight.Launch(Velocity, SpinVector);
            StubControl.DeltaTime = 1f / 60f;
            int frames = 0;
            while (flight.IsFlying && frames++ < 100_000)
            {
                Call(flight, "Update");
                Call(preview, "LateUpdate");
                if (bounces.Count == 1 && preview.Predictions == 2)
                {
                    // The first arc's line ends where the ball bounced (float rounding of tens of metres: 1e-5 m).
                    Assert.That(end.x, Is.EqualTo(bounces[0].Position.X).Within(1e-5));
                    Assert.That(end.z, Is.EqualTo(bounces[0].Position.Z).Within(1e-5));
                }
            }

            // One prediction for the aim, one at the launch, one per bounce; none in the other frames.
            Assert.That(frames, Is.GreaterThan(100));
            Assert.That(preview.Predictions, Is.EqualTo(2 + bounces.Count));
        }

        [Test]
        public void ThePreview_DrawsNothing_BeforeALaunchOrAnAim()
        {
            // A new LineRenderer has two points in Unity, (0, 0, 0) and (0, 0, 1) (so has the stub's): a preview
            // that kept them would draw a stray 1 m line at the world origin until the first launch.
            MagnusBallFlight flight = NewFlight(SurfaceChoice.Preset);
            var holder = new GameObject("line");
            LineRenderer line = holder.AddComponent<LineRenderer>();
            Assert.That(line.positionCount, Is.EqualTo(2), "Unity's new LineRenderer");
            MagnusBallTrajectoryPreview preview = Add<MagnusBallTrajectoryPreview>(holder);
            preview.flight = flight;
            for (int i = 0; i < 3; i++)
            {
                Call(preview, "LateUpdate");
            }

            Assert.That(preview.Predictions, Is.EqualTo(0));
            Assert.That(preview.PointCount, Is.EqualTo(0));
            Assert.That(line.positionCount, Is.EqualTo(0), "nothing drawn before a launch or a Show");
        }

        [Test]
        public void ThePreview_AndTheFlight_AllocateNothingPerFrame()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.Preset, watchNet: true);
            MagnusBallTrajectoryPreview preview = AddPreview(flight);
            int events = 0;
            flight.Bounced += e => events++;
            flight.PlaneCrossed += e => events++;
            Action update = Message(flight, "Update"), lateUpdate = Message(preview, "LateUpdate");
            StubControl.DeltaTime = 1f / 60f;
            // Every run (the helper's warm-up too: the first prediction builds the predictor, first calls JIT the code)
            // is one whole flight from a new launch. The launch allocates its driver by design, so it is unmeasured.
            int frames = 0, predictionsBefore = 0;
            int fewestFrames = int.MaxValue, fewestEvents = int.MaxValue, fewestPredictions = int.MaxValue;
            Action launch = () =>
            {
                events = 0;
                frames = 0;
                predictionsBefore = preview.Predictions;
                flight.Launch(Velocity, SpinVector);
            };
            Action flightFrames = () =>
            {
                while (flight.IsFlying && frames++ < 100_000)
                {
                    update();
                    lateUpdate(); // re-predicts at every bounce
                }

                fewestFrames = Math.Min(fewestFrames, frames);
                fewestEvents = Math.Min(fewestEvents, events);
                fewestPredictions = Math.Min(fewestPredictions, preview.Predictions - predictionsBefore);
            };

            long allocated = Allocation.SteadyStateBytes(launch, flightFrames);
            Assert.That(fewestFrames, Is.GreaterThan(100));
            Assert.That(fewestEvents, Is.GreaterThan(2), "bounces and the net happened in every measured flight");
            Assert.That(fewestPredictions, Is.GreaterThan(2), "and the preview re-predicted in each");
            Assert.That(allocated, Is.EqualTo(0), $"{allocated} B over {frames} frames");

            // And a preview with nothing new to draw allocates nothing either.
            Action idlePreview = () =>
            {
                for (int i = 0; i < 1000; i++)
                {
                    lateUpdate();
                }
            };

            Assert.That(Allocation.SteadyStateBytes(idlePreview), Is.EqualTo(0));
        }
    }
}
