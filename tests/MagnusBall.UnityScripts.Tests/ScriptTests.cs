extern alias InputSystemVariant;
using System;
using MagnusBall.Flight;
using MagnusBall.Components;
using MagnusBall.Samples.TennisScene;
using MagnusBall.Samples.TennisScene.Scripts;
using MagnusBall.Stepping;
using MagnusBall.UnityStubs;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.InputSystem;
using static MagnusBall.UnityScripts.Tests.UnityLoop;
using InputSystemCameraSwitch = InputSystemVariant::MagnusBall.Samples.TennisScene.Scripts.CameraSwitch;
using InputSystemSceneInput = InputSystemVariant::MagnusBall.Samples.TennisScene.Scripts.SceneInput;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The sample scripts, run on the UnityEngine stub as Unity would run them. The stub only stores values,
    /// so these check the scripts' own logic: frame-rate independence, the predicted line, the camera keys
    /// and the court's geometry.
    /// </summary>
    [TestFixture]
    [NonParallelizable] // the stub's Time and Input are static, as Unity's are
    public class ScriptTests
    {
        [TearDown]
        public void ClearInput()
        {
            StubControl.ReleaseKeys();
            StubControl.ConnectKeyboard(false);
        }

        private static TennisBall NewBall(bool fixedUpdate = false)
        {
            var holder = new GameObject("ball");
            TennisBall ball = Add<TennisBall>(holder);
            ball.stepInFixedUpdate = fixedUpdate;
            return ball;
        }

        private static void Frame(TennisBall ball, bool fixedUpdate)
        {
            if (fixedUpdate)
            {
                Call(ball.Flight, "FixedUpdate");
            }

            Call(ball, "Update");
            Call(ball.Flight, "Update");
        }

        private static (System.Collections.Generic.List<FlightEvent> Touches, Vector3 Drawn, Vector3d Stop) FlyAt(float frameDelta, bool fixedUpdate = false)
        {
            TennisBall ball = NewBall(fixedUpdate);
            var touches = new System.Collections.Generic.List<FlightEvent>();
            Call(ball, "Start"); // builds the model from the inspector defaults and launches
            ball.Touched += touches.Add;
            StubControl.DeltaTime = frameDelta;
            Time.fixedDeltaTime = ball.fixedStep;
            for (int frame = 0; frame < 100_000 && ball.IsFlying; frame++)
            {
                Frame(ball, fixedUpdate);
            }

            Assert.That(ball.IsFlying, Is.False, "the ball comes to rest");
            Assert.That(touches.Count, Is.GreaterThanOrEqualTo(2), "it bounces on the hard court");
            for (int frame = 0; frame < 3; frame++)
            {
                Frame(ball, false); // let the render state come to rest
            }

            return (touches, ball.transform.position, ball.Driver.State.Position);
        }

        [Test]
        public void TheBall_BouncesOnTheSameBits_At30And60And144Fps_AndInFixedUpdate()
        {
            (var reference, Vector3 drawn, Vector3d rest) = FlyAt(1f / 60f);
            foreach ((float delta, bool fixedUpdate) in new[] { (1f / 30f, false), (1f / 144f, false), (0f, true) })
            {
                var touches = FlyAt(delta, fixedUpdate).Touches;
                Assert.That(touches.Count, Is.EqualTo(reference.Count));
                for (int i = 0; i < touches.Count; i++)
                {
                    Assert.That(touches[i].Position, Is.EqualTo(reference[i].Position), $"delta {delta}, touch {i}");
                    Assert.That(touches[i].Time, Is.EqualTo(reference[i].Time), $"delta {delta}, touch {i}");
                }
            }

            // The transform ends where the library says, rounded to float (1e-5 m: float has 24 bits, on numbers of tens of metres).
            Assert.That(FlyAt(1f / 144f).Stop, Is.EqualTo(rest), "where it stops rolling");
            Assert.That(drawn.x, Is.EqualTo(rest.X).Within(1e-5));
            Assert.That(drawn.y, Is.EqualTo(rest.Y).Within(1e-5));
            Assert.That(drawn.z, Is.EqualTo(rest.Z).Within(1e-5));
        }

        [Test]
        public void TheInspectorDefaults_AreTheHeadlessFlatServe_AndLandInTheDeuceBox()
        {
            // The inspector's front/top/left defaults are the flat serve's velocity rounded to 0.01 m/s, so the
            // Unity ball and the headless table's first row must land within a few centimetres of each other.
            FlightEvent landing = FlyAt(1f / 60f).Touches[0];
            var headless = new ShotSimulation(new SceneSettings()).Run(StandardShots.FlatServe, Span<Vector3d>.Empty);
            TestContext.Out.WriteLine($"Unity defaults land at {landing.Position}; headless flat serve at {headless.Landing}");
            // 5 cm: the 0.005 m/s rounding of the inspector's velocity moves a 0.44 s flight by well under that.
            Assert.That(landing.Position.X, Is.EqualTo(headless.Landing.X).Within(0.05));
            Assert.That(landing.Position.Z, Is.EqualTo(headless.Landing.Z).Within(0.05));
            Assert.That(TennisCourt.IsIn(TargetArea.FarDeuceServiceBox, landing.Position.X, landing.Position.Z), Is.True);
        }

        [Test]
        public void TheLine_IsThePathTheBallFlies()
        {
            // The scene's line is the package's preview component following the scene's ball.
            TennisBall ball = NewBall();
            Call(ball, "Start");
            var holder = new GameObject("line");
            LineRenderer renderer = holder.AddComponent<LineRenderer>();
            MagnusBallTrajectoryPreview line = Add<MagnusBallTrajectoryPreview>(holder);
            line.flight = ball.Flight;
            Call(line, "LateUpdate");

            Assert.That(renderer.positionCount, Is.GreaterThan(10));
            Vector3 first = renderer.GetPosition(0), last = renderer.GetPosition(renderer.positionCount - 1);
            Assert.That(first.x, Is.EqualTo(ball.servePosition.x));
            Assert.That(first.y, Is.EqualTo(ball.servePosition.y));

            FlightEvent landing = FlyAt(1f / 60f).Touches[0];
            // The line ends at the landing the ball then flies to (float rounding only: 1e-5 m).
            Assert.That(last.x, Is.EqualTo(landing.Position.X).Within(1e-5));
            Assert.That(last.z, Is.EqualTo(landing.Position.Z).Within(1e-5));
        }

        [Test]
        public void F1_ShowsTheSecondaryCamera_F2_ThePrimary_ThroughTheInputManager()
        {
            var primary = new Camera();
            var secondary = new Camera();
            var cameras = new CameraSwitch { primaryCamera = primary, secondaryCamera = secondary };
            Call(cameras, "Start");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));

            // This variant is compiled with ENABLE_LEGACY_INPUT_MANAGER: a key pressed in the Input System is not seen.
            StubControl.ConnectKeyboard(true);
            StubControl.InputSystemKeysDown.Add(Key.F1);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));

            StubControl.LegacyKeysDown.Add(KeyCode.F1);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((false, true)));

            StubControl.ReleaseKeys();
            StubControl.LegacyKeysDown.Add(KeyCode.F2);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));
        }

        [Test]
        public void F1_ShowsTheSecondaryCamera_F2_ThePrimary_ThroughTheInputSystem()
        {
            var primary = new Camera();
            var secondary = new Camera();
            var cameras = new InputSystemCameraSwitch { primaryCamera = primary, secondaryCamera = secondary };
            Call(cameras, "Start");

            // Compiled with ENABLE_INPUT_SYSTEM: the Input Manager is not read (in Unity it would throw), and
            // without a keyboard nothing is pressed.
            StubControl.LegacyKeysDown.Add(KeyCode.F1);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));

            StubControl.ConnectKeyboard(true);
            StubControl.InputSystemKeysDown.Add(Key.F1);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((false, true)));

            StubControl.ReleaseKeys();
            StubControl.InputSystemKeysDown.Add(Key.F2);
            Call(cameras, "Update");
            Assert.That((primary.enabled, secondary.enabled), Is.EqualTo((true, false)));
        }

        [TestCase(KeyCode.Space, Key.Space)]
        [TestCase(KeyCode.A, Key.A)]
        [TestCase(KeyCode.R, Key.R)]
        [TestCase(KeyCode.Z, Key.Z)]
        [TestCase(KeyCode.F1, Key.F1)]
        [TestCase(KeyCode.F12, Key.F12)]
        [TestCase(KeyCode.Alpha0, Key.Digit0)]
        [TestCase(KeyCode.Alpha9, (Key)49)] // Digit9: Digit1 (41) + 8
        public void KeyCodes_MapToTheInputSystemsKeys(KeyCode code, Key key) =>
            Assert.That(InputSystemSceneInput.ToInputSystem(code), Is.EqualTo(key));

        [Test]
        public void Space_Launches_R_Resets_InEitherBackend()
        {
            TennisBall ball = NewBall();
            ball.launchOnStart = false;
            Call(ball, "Start");
            Assert.That(ball.IsFlying, Is.False);
            StubControl.LegacyKeysDown.Add(KeyCode.Space);
            Frame(ball, false);
            Assert.That(ball.IsFlying, Is.True);
            StubControl.ReleaseKeys();
            StubControl.LegacyKeysDown.Add(KeyCode.R);
            Frame(ball, false);
            Assert.That(ball.IsFlying, Is.False);
            Assert.That(ball.transform.position.x, Is.EqualTo(ball.servePosition.x), "back at the serving position");
        }

        [Test]
        public void TheCourt_IsBuiltToItfDimensions()
        {
            var holder = new GameObject();
            CourtBuilder court = holder.AddComponent<CourtBuilder>();
            court.Build();
            Transform root = holder.transform.Find(CourtBuilder.RootName);
            var parts = new System.Collections.Generic.List<GameObject>();
            for (int i = 0; i < root.childCount; i++)
            {
                parts.Add(root.GetChild(i).gameObject);
            }

            GameObject surface = parts.Find(p => p.name == "court")!;
            Assert.That(surface.transform.localScale.x, Is.EqualTo(23.77f));
            Assert.That(surface.transform.localScale.z, Is.EqualTo(10.97f));

            // The net: 0.914 m in the middle, 1.07 m at the posts (within half a slice of the sloping cord: 1 cm).
            var net = parts.FindAll(p => p.name == "net");
            float lowest = float.MaxValue, highest = 0;
            foreach (GameObject slice in net)
            {
                lowest = Math.Min(lowest, slice.transform.localScale.y);
                highest = Math.Max(highest, slice.transform.localScale.y);
            }

            Assert.That(lowest, Is.EqualTo(0.914f).Within(0.01));
            Assert.That(highest, Is.EqualTo(1.07f).Within(0.01));
            GameObject post = parts.Find(p => p.name == "net post")!;
            Assert.That(Math.Abs(post.transform.localPosition.z), Is.EqualTo(10.97f / 2 + 0.914f).Within(1e-5));

            // Every line lies inside the doubles outline (dimensions are to the lines' outer edges).
            foreach (GameObject line in parts.FindAll(p => p.name.Contains("line") || p.name.Contains("mark")))
            {
                Vector3 c = line.transform.localPosition, s = line.transform.localScale;
                Assert.That(Math.Abs(c.x) + s.x / 2, Is.LessThanOrEqualTo(23.77f / 2 + 1e-4), line.name);
                Assert.That(Math.Abs(c.z) + s.z / 2, Is.LessThanOrEqualTo(10.97f / 2 + 1e-4), line.name);
            }
        }

        [Test]
        public void TheCourt_BuiltInEditMode_IsNotBuiltAgainOnPlay_AndSharesFourMaterials()
        {
            var holder = new GameObject();
            CourtBuilder court = holder.AddComponent<CourtBuilder>();
            int before = StubControl.MaterialsCreated;
            court.Build(); // the "Build court" context menu, in edit mode
            Transform built = holder.transform.Find(CourtBuilder.RootName);
            int parts = built.childCount;
            Assert.That(StubControl.MaterialsCreated - before, Is.EqualTo(4), "one material per colour, none per part (renderer.material would copy one per part)");

            Call(court, "Start"); // Play
            Assert.That(holder.transform.childCount, Is.EqualTo(1), "one court");
            Assert.That(holder.transform.Find(CourtBuilder.RootName), Is.SameAs(built), "Start keeps the court built in edit mode");

            court.Build(); // the context menu again: replaces the court
            Assert.That(holder.transform.childCount, Is.EqualTo(1));
            Assert.That(holder.transform.Find(CourtBuilder.RootName).childCount, Is.EqualTo(parts));
            Assert.That(built == null, Is.True, "the old court is destroyed (Unity's destroyed-object null)");
        }

        [Test]
        public void TheCourt_RebuiltAfterADomainReload_DestroysTheOldBuildsMaterials_AndNoOther()
        {
            // After a domain reload (or with the scene reopened) the builder's private fields are new: the materials of
            // the court saved with the scene are found on its parts by their name. Before, they were kept in a private
            // array, lost on reload, so every later rebuild in the editor leaked four materials into the scene.
            var holder = new GameObject();
            holder.AddComponent<CourtBuilder>().Build();
            Transform built = holder.transform.Find(CourtBuilder.RootName);
            var old = new System.Collections.Generic.HashSet<Material>();
            for (int i = 0; i < built.childCount; i++)
            {
                old.Add(built.GetChild(i).GetComponent<Renderer>().sharedMaterial);
            }

            Assert.That(old.Count, Is.EqualTo(4));
            foreach (Material m in old)
            {
                Assert.That(m.name, Does.StartWith(CourtBuilder.MaterialPrefix));
            }

            CourtBuilder reloaded = holder.AddComponent<CourtBuilder>(); // a builder with fresh fields, as after a reload
            reloaded.Build();
            foreach (Material m in old)
            {
                Assert.That(m == null, Is.True, "an old build's material is destroyed");
            }

            Assert.That(StubControl.DefaultMaterial == null, Is.False, "the primitives' shared default material is not the builder's");
            Assert.That(holder.transform.childCount, Is.EqualTo(1), "one court");
        }
    }
}
