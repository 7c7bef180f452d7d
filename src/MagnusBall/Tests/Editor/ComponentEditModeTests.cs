#nullable enable
using System;
using System.Collections.Generic;
using System.Reflection;
using MagnusBall.Components;
using MagnusBall.Flight;
using MagnusBall.Presets;
using NUnit.Framework;
using UnityEngine;

namespace MagnusBall.Tests.Editor
{
    /// <summary>
    /// Edit Mode tests of the package's components (Unity Test Framework; no frame loop needed): the preset drop-down and
    /// its migration from old scenes, refusals naming the inspector field, inspector edits applied through OnValidate, the
    /// launch UnityEvent, help links. In Unity: add "testables": ["com.magnusball.core"] to Packages/manifest.json, then
    /// Window > General > Test Runner > Edit Mode. The repository's CI compiles and runs the same file against its
    /// UnityEngine stub (tests/MagnusBall.UnityScripts.Tests).
    /// </summary>
    public class ComponentEditModeTests
    {
        private readonly List<GameObject> _made = new List<GameObject>();

        [TearDown]
        public void DestroyTheObjects()
        {
            foreach (GameObject made in _made)
            {
                UnityEngine.Object.DestroyImmediate(made);
            }

            _made.Clear();
        }

        private T NewComponent<T>(string name)
            where T : Component
        {
            var holder = new GameObject(name);
            _made.Add(holder);
            return holder.AddComponent<T>();
        }

        // Unity calls OnValidate after an inspector edit; a test calls the private message the same way Unity finds it, by name.
        private static void InspectorEdited(object component) =>
            component.GetType().GetMethod("OnValidate", BindingFlags.Instance | BindingFlags.NonPublic)!.Invoke(component, null);

        [Test]
        public void ThePresetDropDown_OffersEveryPreset_OnceEach()
        {
            var names = new List<string>();
            foreach (PresetChoice choice in (PresetChoice[])Enum.GetValues(typeof(PresetChoice)))
            {
                var settings = new FlightSettings { presetChoice = choice };
                names.Add(settings.Preset().Name);
            }

            Assert.That(names, Is.EquivalentTo(SportPresets.Names));
        }

        [Test]
        public void ThePresetByName_PicksTheDropDownsValue_AndAnUnknownNameIsRefusedAtOnce()
        {
            var settings = new FlightSettings { preset = "golf_linear_2023" };
            Assert.That(settings.presetChoice, Is.EqualTo(PresetChoice.GolfLinear2023));
            var refused = Assert.Throws<ArgumentException>(() => settings.preset = "squash")!;
            Assert.That(refused.ParamName, Is.EqualTo("preset"));
            Assert.That(settings.presetChoice, Is.EqualTo(PresetChoice.GolfLinear2023), "unchanged");
        }

        [Test]
        public void AComponentSavedWithTheOldPresetText_LoadsWithTheDropDownSet()
        {
            var settings = new FlightSettings();
            // What [FormerlySerializedAs("preset")] does when Unity loads an old scene, then Unity's callback after loading.
            typeof(FlightSettings).GetField("legacyPresetName", BindingFlags.Instance | BindingFlags.NonPublic)!.SetValue(settings, "basketball");
            ((ISerializationCallbackReceiver)settings).OnAfterDeserialize();
            Assert.That(settings.presetChoice, Is.EqualTo(PresetChoice.Basketball));
            Assert.That(settings.Preset().Ball.Radius, Is.EqualTo(SportPresets.Basketball.Ball.Radius));
        }

        [Test]
        public void ABadField_IsRefusedByApplySettings_NamingIt_AndTheOldSettingsStay()
        {
            MagnusBallFlight flight = NewComponent<MagnusBallFlight>("ball");
            flight.ApplySettings();
            FlightModel before = flight.Model;
            flight.settings.airDensity = -1f;
            var refused = Assert.Throws<ArgumentException>(() => flight.ApplySettings())!;
            Assert.That(refused.ParamName, Is.EqualTo("airDensity"));
            Assert.That(flight.Model, Is.SameAs(before));
        }

        [Test]
        public void AnInspectorEdit_IsAppliedThroughOnValidate()
        {
            MagnusBallFlight flight = NewComponent<MagnusBallFlight>("ball");
            Assert.That(flight.Model.Ball.Mass, Is.EqualTo(SportPresets.Tennis.Ball.Mass));
            flight.settings.presetChoice = PresetChoice.Soccer;
            flight.fixedStep = 1f / 120f;
            InspectorEdited(flight);
            Assert.That(flight.Model.Ball.Mass, Is.EqualTo(SportPresets.Soccer.Ball.Mass));
            Assert.That(flight.FixedStep, Is.EqualTo((double)(1f / 120f)));
        }

        [Test]
        public void ALaunch_RaisesTheCSharpEvent_ThenTheUnityEvent_WithTheStart()
        {
            MagnusBallFlight flight = NewComponent<MagnusBallFlight>("ball");
            flight.transform.position = new Vector3(0f, 1f, 0f);
            var order = new List<string>();
            FlightState started = default;
            flight.Launched += s =>
            {
                started = s;
                order.Add("C#");
            };
            flight.onLaunched.AddListener(() => order.Add("UnityEvent"));
            flight.Launch(new Vector3(20f, 5f, 0f), topspinRpm: 1000f, sidespinRpm: 0f);
            Assert.That(order, Is.EqualTo(new[] { "C#", "UnityEvent" }));
            Assert.That(started.Position.Y, Is.EqualTo(1.0));
            Assert.That(started.Velocity.X, Is.EqualTo(20.0));
            Assert.That(flight.IsFlying, Is.True);
        }

        [Test]
        public void ARefusedLaunch_RaisesNoLaunchEvent()
        {
            MagnusBallFlight flight = NewComponent<MagnusBallFlight>("ball");
            int launches = 0;
            flight.onLaunched.AddListener(() => launches++);
            Assert.Throws<ArgumentOutOfRangeException>(() => flight.Launch(new Vector3(20f, 5f, 0f), topspinRpm: float.NaN, sidespinRpm: 0f));
            Assert.That(launches, Is.EqualTo(0));
            Assert.That(flight.IsFlying, Is.False);
        }

        [TestCase(typeof(MagnusBallFlight))]
        [TestCase(typeof(MagnusBallRigidbody))]
        [TestCase(typeof(MagnusBallTrajectoryPreview))]
        public void EveryComponent_OpensTheManualFromItsHelpIcon(Type component)
        {
            var help = (HelpURLAttribute)Attribute.GetCustomAttribute(component, typeof(HelpURLAttribute))!;
            Assert.That(help, Is.Not.Null);
            Assert.That(help.URL, Does.StartWith("https://").And.Contain("Documentation~/MagnusBall.md#"));
        }
    }
}
