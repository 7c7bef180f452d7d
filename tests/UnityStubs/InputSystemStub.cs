// A STUB of the part of the Input System package (com.unity.inputsystem) the TennisScene sample reads when
// ENABLE_INPUT_SYSTEM is defined: Keyboard.current, its indexer by Key, and KeyControl.wasPressedThisFrame,
// with the package's names and signatures (unity-api-reference.txt lists them with the source file checked).
// Tests press keys through MagnusBall.UnityStubs.StubControl.
using MagnusBall.UnityStubs;
using UnityEngine.InputSystem.Controls;

namespace UnityEngine.InputSystem
{
    public enum Key
    {
        None = 0,
        Space = 1,
        A = 15,
        R = 32,
        Z = 40,
        Digit1 = 41,
        Digit0 = 50,
        F1 = 94,
        F2 = 95,
        F12 = 105,
    }

    public class Keyboard
    {
        public static Keyboard current { get; private set; }

        internal static void StubSetCurrent(Keyboard keyboard) => current = keyboard;

        private readonly KeyControl[] _keys = new KeyControl[128];

        // The package keeps one control per key; so does the stub (reading a key allocates nothing). As in the
        // package, a key with no control (Key.None, or past the last key) throws ArgumentOutOfRangeException.
        public KeyControl this[Key key] =>
            key > Key.None && (int)key < _keys.Length
                ? _keys[(int)key] ?? (_keys[(int)key] = new KeyControl { keyCode = key })
                : throw new System.ArgumentOutOfRangeException(nameof(key));
    }
}

namespace UnityEngine.InputSystem.Controls
{
    public class ButtonControl
    {
        public ButtonControl()
        {
        }

        public bool wasPressedThisFrame => this is KeyControl key && StubControl.InputSystemKeysDown.Contains(key.keyCode);
    }

    public class KeyControl : ButtonControl
    {
        public Key keyCode { get; set; }
    }
}
